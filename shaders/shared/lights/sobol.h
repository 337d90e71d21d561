// Low-discrepancy numbers for the path's dimensions (issue 46): Owen-scrambled Sobol points with
// padding, counter-based like random.h's rnd, so both backends draw the same bits and sample
// ranges drawn apart still merge into the whole render.
//
// The variant: padded 2D Sobol with hash-based Owen scrambling and a shuffled index, as Burley's
// "Practical Hash-based Owen Scrambling" (JCGT 9(4), 2020) and pbrt-v4's PaddedSobolSampler.
// Every pair of dimensions (and every single dimension) is its own copy of Sobol's first two
// dimensions, the only pair of Sobol's that is a (0, 2)-sequence in base 2: the first 2^k samples
// of a pixel are a (0, k, 2)-net in every pair (each elementary interval of area 2^-k holds one
// point), for every k at once. Each pair's copy
//   - takes the sample index through a nested uniform scramble seeded by (pixel, pair): samples
//     0 .. 2^k - 1 become an aligned block of 2^k points of the sequence in some order, still a
//     net, but another block and order for every pair, so pairs are not correlated with each
//     other (padding), and no sample count is needed (pbrt's PermutationElement needs one);
//   - Owen-scrambles each coordinate by a hash (Laine and Karras' construction with Vegdahl's
//     constants, "Building a better LK hash", 2021, which pbrt-v4's FastOwenScrambler uses):
//     a nested uniform scramble keeps every net a net and makes each pixel's points uniformly
//     distributed, with the error's faster convergence for smooth integrands (Owen 1997).
// Not Burley's 4D variant: its dimensions 2 and 3 need generator tables, and their pairs with
// 0 and 1 are not (0, 2)-nets. Here the two generator matrices are computed in registers: the
// first is the bit reversal, the second Pascal's triangle mod 2 (sobol_second). 32-bit integer
// arithmetic only, no tables, no state: the numbers are a function of (seed, pixel, sample index,
// bounce, dimension), as rnd's.
//
// Use: sobol_rnd(s, dim) and sobol_rnd2(s, dim) for the stream s of a pixel sample at a bounce
// (random.h's pixel_sample_stream and at_bounce carry the pixel's key and the sample index for
// this), with random.h's dimension names; a pair is named by its first dimension, and its first
// number is that dimension's sobol_rnd. Floats as rnd's: the top 24 bits, exact in [0, 1).
#ifndef RTVK_SOBOL_H
#define RTVK_SOBOL_H
#include "kernel_lang.h"
#include "random.h"

RTVK_KERNELS_BEGIN

// Sobol points as 32-bit fractions: bit 31 is worth 1/2. The first dimension is the index's bits
// reversed (van der Corput's radical inverse in base 2).
inline uint sobol_first(uint index) {
  return bitfieldReverse(index);
}

// The second dimension: index bit j adds generator column j, whose fraction bit 31 - i is set
// where i's bits are a subset of j's (the binomial C(j, i) is odd: Pascal's triangle mod 2, the
// columns the recurrence v_j = v_(j-1) ^ (v_(j-1) >> 1) of the polynomial x + 1 makes). So bit
// 31 - i of the point is bit i of sobol_pascal(index), the parity of the index's bits j that are
// supersets of i: five steps of a superset sum over the 5-bit positions.
inline uint sobol_pascal(uint index) {
  uint x = index;
  x ^= (x >> 1u) & 0x55555555u;  // positions without bit 0 gather those with it
  x ^= (x >> 2u) & 0x33333333u;
  x ^= (x >> 4u) & 0x0f0f0f0fu;
  x ^= (x >> 8u) & 0x00ff00ffu;
  x ^= (x >> 16u) & 0x0000ffffu;
  return x;
}
inline uint sobol_second(uint index) {
  return bitfieldReverse(sobol_pascal(index));
}

// A bijection of 32-bit words whose bit i depends on bits 0 .. i only (multiplications by even
// constants, an addition and a multiplication by an odd one), seeded: Laine and Karras's
// construction with Vegdahl's constants.
inline uint laine_karras_permutation(uint x, uint seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16u) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Owen's nested uniform scramble of a 32-bit fraction, hashed: each bit flips or not by a
// function of the seed and the bits above it, so every dyadic interval maps onto one of the same
// size, and a net stays a net.
inline uint nested_uniform_scramble(uint x, uint seed) {
  return bitfieldReverse(laine_karras_permutation(bitfieldReverse(x), seed));
}

// The seed of a dimension (or of a pair, by its first dimension) of one pixel's samples at one
// bounce: the pixel's key with rnd's counter (bounce << 4 | dim), spread by an odd multiplier
// (one to one) and offset so that no seed is rnd's key of sample 0, hashed once.
inline uint sobol_seed(random_stream s, uint dim) {
  return hash32(s.pixel_key ^ (((s.bounce << 4u) | dim) * 0x9e3779b9u + 0x50b01u));
}

// The sample's index in the pair's copy of the sequence, and the two coordinates' scramble seeds.
inline uint sobol_index(uint sample_index, uint seed) {
  return nested_uniform_scramble(sample_index, seed);
}
inline uint sobol_seed_x(uint seed) {
  return hash32(seed ^ 0xa511e9b3u);
}
inline uint sobol_seed_y(uint seed) {
  return hash32(seed ^ 0x63d83595u);
}

// The 32 bits of dimension `dim`, and of the pair that begins at `dim`: the scrambles of
// sobol_first and sobol_second of sobol_index, written with the reversals that cancel left out
// (nested_uniform_scramble(sobol_first(i), s) = bitfieldReverse(laine_karras_permutation(i, s)),
// and likewise sobol_second's with sobol_pascal(i)): 3 and 4 reversals, not 6 and 8.
inline uint sobol_bits(random_stream s, uint dim) {
  uint seed = sobol_seed(s, dim);
  uint index = sobol_index(s.sample_index, seed);
  return bitfieldReverse(laine_karras_permutation(index, sobol_seed_x(seed)));
}

inline uvec2 sobol_bits2(random_stream s, uint dim) {
  uint seed = sobol_seed(s, dim);
  uint index = sobol_index(s.sample_index, seed);
  return uvec2(bitfieldReverse(laine_karras_permutation(index, sobol_seed_x(seed))),
               bitfieldReverse(laine_karras_permutation(sobol_pascal(index), sobol_seed_y(seed))));
}

// A low-discrepancy number in [0, 1), rounded as rnd's (the top 24 bits).
inline precise real sobol_rnd(random_stream s, uint dim) {
  return real(bits_to_unit(sobol_bits(s, dim)));
}

// The pair of dimensions (dim, dim + 1) as one 2D point: (0, k, 2)-nets over a pixel's samples.
inline precise real2 sobol_rnd2(random_stream s, uint dim) {
  uvec2 b = sobol_bits2(s, dim);
  return real2(real(bits_to_unit(b.x)), real(bits_to_unit(b.y)));
}

RTVK_KERNELS_END

#endif  // RTVK_SOBOL_H
