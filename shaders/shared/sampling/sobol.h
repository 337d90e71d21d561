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
// This file holds the bit arithmetic; random.h seeds it from a pixel sample's stream (sobol_rnd,
// sobol_rnd2) and draws from it wherever a stream asks for low-discrepancy numbers (rnd).
#ifndef RTVK_SOBOL_H
#define RTVK_SOBOL_H
#include "kernel_lang.h"

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

RTVK_KERNELS_END

#endif  // RTVK_SOBOL_H
