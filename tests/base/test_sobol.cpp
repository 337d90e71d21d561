// sobol.h's low-discrepancy numbers: Sobol's generators, nets in every pair of every pixel,
// decorrelated pixels, pairs and bounces, uniform marginals, and an error that falls faster than
// with rnd's independent numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <set>
#include <vector>

#include "medium.h"
#include "random.h"

namespace rtvk {
namespace {

// Known answers computed by an independent Python implementation (Sobol's second dimension by
// its direction numbers' recurrence, the scramble and hashes written out).
TEST(Sobol, KnownAnswers) {
  EXPECT_EQ(sobol_bits2(pixel_sample_stream(0, 0, 0), 0), uvec2(0x6783afe7u, 0x8f5df841u));
  EXPECT_EQ(sobol_bits2(at_bounce(pixel_sample_stream(7, 12345, 3), 2), 1),
            uvec2(0x14c93b66u, 0xc1ce0df2u));
  EXPECT_EQ(sobol_bits2(at_bounce(pixel_sample_stream(1, 99, 255), 5), 7),
            uvec2(0x0d4af351u, 0xe777823eu));
  EXPECT_EQ(sobol_bits2(at_bounce(pixel_sample_stream(0xffffffffu, 0xffffffffu, 1000000), 50), 15),
            uvec2(0x359aab48u, 0x33f383efu));
  EXPECT_EQ(sobol_rnd2(at_bounce(pixel_sample_stream(7, 12345, 3), 2), 1),
            real2(0.08119553327560425, 0.7570503354072571));
  // The pieces the header names compose into the same bits.
  const random_stream s = at_bounce(pixel_sample_stream(7, 12345, 3), 2);
  const uint seed = sobol_seed(s, 1), index = sobol_index(3, seed);
  EXPECT_EQ(sobol_bits2(s, 1),
            uvec2(nested_uniform_scramble(sobol_first(index), sobol_seed_x(seed)),
                  nested_uniform_scramble(sobol_second(index), sobol_seed_y(seed))));
}

// The stream carries the pixel's key and the sample index beside rnd's key, through at_bounce,
// and rnd's key is still sample_key (rnd's numbers unchanged: Random.KnownAnswers).
TEST(Sobol, TheStreamCarriesThePixelAndTheSampleIndex) {
  const random_stream s = at_bounce(pixel_sample_stream(7, 12345, 3), 2);
  EXPECT_EQ(s.key, sample_key(7, 12345, 3));
  EXPECT_EQ(s.pixel_key, pixel_key(7, 12345));
  EXPECT_EQ(s.sample_index, 3u);
  EXPECT_EQ(s.bounce, 2u);
}

// A stream asked for low-discrepancy numbers (next-event estimation's paths) draws them in every
// dimension through rnd, the pairs' seconds as their pair's second coordinate, through at_bounce
// and in the media's own streams; a hashed stream's rnd is unchanged.
TEST(Sobol, ALowDiscrepancyStreamDrawsSobolInEveryDimension) {
  const random_stream hashed = at_bounce(pixel_sample_stream(7, 12345, 3), 2);
  const random_stream s = at_bounce(with_low_discrepancy(pixel_sample_stream(7, 12345, 3)), 2);
  EXPECT_FALSE(hashed.low_discrepancy);
  EXPECT_TRUE(s.low_discrepancy);
  EXPECT_EQ(rnd(hashed, 5), bits_to_unit(random_bits(7, 12345, 3, 2, 5)));
  for (uint dim = 0; dim < 16; ++dim) {
    const bool second = dim == 1 || dim == 3 || dim == 8 || dim == 12;
    const float want = second ? float(sobol_rnd2(s, dim - 1).y) : float(sobol_rnd(s, dim));
    EXPECT_EQ(rnd(s, dim), want) << "dimension " << dim;
    EXPECT_NE(rnd(s, dim), rnd(hashed, dim)) << "dimension " << dim;
  }
  // Two media in one stream draw apart (their own pixel keys as well as keys).
  EXPECT_NE(medium_random(s, 0, dim_medium), medium_random(s, 1, dim_medium));
  EXPECT_NE(medium_random(s, 0, dim_medium), medium_random(s, 0, dim_shadow_medium));
}

TEST(Sobol, TheGeneratorsAreSobolsFirstTwoDimensions) {
  // Dimension 2's direction numbers by their recurrence (polynomial x + 1, m_1 = 1).
  const auto by_columns = [](uint index) {
    uint column = 0x80000000u, bits = 0;
    for (int j = 0; j < 32; ++j, column ^= column >> 1)
      if (index >> j & 1u) bits ^= column;
    return bits;
  };
  EXPECT_EQ(sobol_second(1), 0x80000000u);
  EXPECT_EQ(sobol_second(2), 0xc0000000u);
  EXPECT_EQ(sobol_second(3), 0x40000000u);
  EXPECT_EQ(sobol_second(4), 0xa0000000u);
  EXPECT_EQ(sobol_first(1), 0x80000000u);
  EXPECT_EQ(sobol_first(6), 0x60000000u);
  for (uint i = 0; i < 5000; ++i) {
    const uint index = i < 2500 ? i : hash32(i);
    ASSERT_EQ(sobol_second(index), by_columns(index)) << index;
    uint reversed = 0;
    for (int j = 0; j < 32; ++j) reversed |= (index >> j & 1u) << (31 - j);
    ASSERT_EQ(sobol_first(index), reversed) << index;
  }
}

// Owen's scramble maps the 2^k dyadic intervals of width 2^-k onto themselves, one to one, and
// two points in one interval of width 2^-j stay together (bits below the top k do not matter).
TEST(Sobol, TheScrambleKeepsDyadicIntervalsNested) {
  for (const uint seed : {0u, 1u, 0x12345678u, hash32(99)}) {
    for (int k = 1; k <= 10; ++k) {
      std::set<uint> tops;
      for (uint x = 0; x < (1u << k); ++x) {
        const uint low = hash32(x + seed) >> k;  // any bits below the top k
        const uint a = nested_uniform_scramble(x << (32 - k), seed);
        const uint b = nested_uniform_scramble((x << (32 - k)) | low, seed);
        ASSERT_EQ(a >> (32 - k), b >> (32 - k)) << "k " << k << " x " << x;
        tops.insert(a >> (32 - k));
      }
      EXPECT_EQ(tops.size(), std::size_t(1) << k) << "k " << k << " seed " << seed;
    }
  }
}

// Each pixel's samples [m 2^k, (m + 1) 2^k) of every pair are a (0, k, 2)-net in base 2: every
// elementary interval [a 2^-i, (a+1) 2^-i) x [b 2^-(k-i), (b+1) 2^-(k-i)) holds one point.
bool is_net(const std::vector<real2>& points, int k) {
  for (int i = 0; i <= k; ++i) {
    std::vector<int> count(std::size_t(1) << k, 0);
    for (const real2 p : points) {
      const auto a = std::size_t(std::ldexp(p.x, i)), b = std::size_t(std::ldexp(p.y, k - i));
      if (++count[(a << (k - i)) | b] > 1) return false;
    }
  }
  return true;
}

TEST(Sobol, EachPairOfEachPixelIsANetAtEveryPowerOfTwo) {
  for (const uint pixel : {0u, 1u, 777u, 123456u})
    for (const uint bounce : {0u, 1u, 7u})
      for (const uint dim : {dim_jitter_u, dim_lens_a, dim_light_a, dim_alpha})
        for (int k = 0; k <= 10; k += 2)
          for (const uint block : {0u, 3u}) {
            std::vector<real2> points;
            std::vector<real> line;
            for (uint i = block << k; i < (block + 1) << k; ++i) {
              const random_stream s = at_bounce(pixel_sample_stream(42, pixel, i), bounce);
              points.push_back(sobol_rnd2(s, dim));
              line.push_back(sobol_rnd(s, dim));
              ASSERT_EQ(points.back().x, line.back());  // a pair begins with its dimension's number
              ASSERT_GE(std::min(points.back().x, points.back().y), 0.0);
              ASSERT_LT(std::max(points.back().x, points.back().y), 1.0);
            }
            EXPECT_TRUE(is_net(points, k)) << "pixel " << pixel << " bounce " << bounce << " dim "
                                           << dim << " 2^" << k << " samples from " << (block << k);
            std::set<int> strata;  // one dimension alone: each interval of 2^-k once
            for (const real x : line) strata.insert(int(std::ldexp(x, k)));
            EXPECT_EQ(strata.size(), std::size_t(1) << k) << "pixel " << pixel << " dim " << dim;
          }
}

// Pearson's correlation of two sequences.
double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= double(a.size()), mb /= double(b.size());
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    ab += (a[i] - ma) * (b[i] - mb), aa += (a[i] - ma) * (a[i] - ma),
        bb += (b[i] - mb) * (b[i] - mb);
  return ab / std::sqrt(aa * bb);
}

// Over one pixel's 256 samples, the numbers of two pairs, of two pixels, of two bounces are not
// correlated: the mean |correlation| over 256 pixels is near independent numbers' (about
// 0.8 / sqrt(256) = 0.05). Measured 0.059 to 0.063: the shuffle keeps samples 2m and 2m + 1 in
// opposite halves in every dimension (they are an aligned block of two), so half as many
// independent top bits meet (1.06 / sqrt(n) expected), with no bias. Without the index's shuffle,
// two pairs' first numbers are scrambles of one van der Corput point and agree in their top bit
// always or never (|correlation| about 0.7).
TEST(Sobol, PixelsPairsAndBouncesAreDecorrelated) {
  const int n = 256, pixels = 256;
  using draw = std::function<double(uint pixel, uint sample)>;
  const auto number = [](uint pixel, uint sample, uint bounce, uint dim, bool second) {
    const real2 p = sobol_rnd2(at_bounce(pixel_sample_stream(3, pixel, sample), bounce), dim);
    return second ? p.y : p.x;
  };
  const std::vector<std::pair<const char*, std::pair<draw, draw>>> cases = {
      {"two pairs' first numbers",
       {[&](uint p, uint i) { return number(p, i, 1, dim_direction_a, false); },
        [&](uint p, uint i) { return number(p, i, 1, dim_light_a, false); }}},
      {"two pairs' second numbers",
       {[&](uint p, uint i) { return number(p, i, 0, dim_jitter_u, true); },
        [&](uint p, uint i) { return number(p, i, 0, dim_lens_a, true); }}},
      {"one pair at two bounces",
       {[&](uint p, uint i) { return number(p, i, 1, dim_direction_a, false); },
        [&](uint p, uint i) { return number(p, i, 2, dim_direction_a, false); }}},
      {"a pixel and the next",
       {[&](uint p, uint i) { return number(2 * p, i, 0, dim_jitter_u, false); },
        [&](uint p, uint i) { return number(2 * p + 1, i, 0, dim_jitter_u, false); }}},
      {"one dimension and the next, alone",
       {[&](uint p, uint i) {
          return double(sobol_rnd(at_bounce(pixel_sample_stream(3, p, i), 1), dim_fuzz_radius));
        },
        [&](uint p, uint i) {
          return double(sobol_rnd(at_bounce(pixel_sample_stream(3, p, i), 1), dim_choice));
        }}}};
  for (const auto& [name, draws] : cases) {
    double mean_abs = 0;
    for (uint p = 0; p < pixels; ++p) {
      std::vector<double> a, b;
      for (uint i = 0; i < n; ++i) a.push_back(draws.first(p, i)), b.push_back(draws.second(p, i));
      mean_abs += std::abs(correlation(a, b)) / pixels;
      ASSERT_NE(a, b) << name;
    }
    std::printf("%s: mean |correlation| %.4f\n", name, mean_abs);
    EXPECT_LT(mean_abs, 0.085) << name;
  }
}

// Across pixels (one sample index each) the numbers are uniform: Kolmogorov-Smirnov for one
// dimension, a chi-square over 16 x 16 cells for a pair.
TEST(Sobol, MarginalsAreUniformAcrossPixels) {
  const uint pixels = 1u << 16;
  for (const uint sample : {0u, 5u, 1000u}) {
    std::vector<double> xs;
    std::vector<int> cells(256, 0);
    for (uint p = 0; p < pixels; ++p) {
      const random_stream s = at_bounce(pixel_sample_stream(11, p, sample), 2);
      xs.push_back(sobol_rnd(s, dim_mixture));
      const real2 q = sobol_rnd2(s, dim_direction_a);
      ++cells[std::size_t(q.x * 16) * 16 + std::size_t(q.y * 16)];
    }
    std::sort(xs.begin(), xs.end());
    double d = 0;
    for (std::size_t i = 0; i < xs.size(); ++i)
      d = std::max(
          {d, double(i + 1) / double(xs.size()) - xs[i], xs[i] - double(i) / double(xs.size())});
    EXPECT_LT(d * std::sqrt(double(pixels)), 1.95) << "sample " << sample;  // p = 0.001
    const double expected = pixels / 256.0;
    double chi2 = 0;
    for (const int c : cells) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_LT(chi2, 255 + 5 * std::sqrt(2 * 255.0)) << "sample " << sample;  // 5 sigma
  }
}

// The RMS error over pixels of the mean of f over each pixel's first n samples of a pair.
double rms_error(const std::function<double(real2)>& f, double exact, uint n, bool sobol) {
  const uint pixels = 512;
  double sum_sq = 0;
  for (uint p = 0; p < pixels; ++p) {
    double mean = 0;
    for (uint i = 0; i < n; ++i) {
      const random_stream s = at_bounce(pixel_sample_stream(5, p, i), 1);
      const real2 q = sobol ? sobol_rnd2(s, dim_direction_a)
                            : real2(rnd(s, dim_direction_a), rnd(s, dim_direction_b));
      mean += f(q) / n;
    }
    sum_sq += (mean - exact) * (mean - exact);
  }
  return std::sqrt(sum_sq / pixels);
}

// The slope of log error against log n from 16 to 256 samples, and the error at 256. Owen's
// scrambled nets: n^-1.5 for smooth integrands, n^-0.75 for a disk's edge; independent numbers
// n^-0.5. Measured over 512 pixels: smooth -1.39 (sobol) / -0.50 (rnd), disk -0.83 / -0.49; at
// 256 samples the error is 81 (smooth) and 3.9 (disk) times smaller than rnd's. Without Owen's
// scramble (the shuffle alone) the smooth slope is -1.02 and the disk's ratio 1.8.
TEST(Sobol, TheErrorFallsFasterThanWithIndependentNumbers) {
  // exp(x y) over the unit square: the sum of 1 / (k k!), k >= 1.
  double smooth_exact = 0, factorial = 1;
  for (int k = 1; k < 20; ++k) factorial *= k, smooth_exact += 1 / (k * factorial);
  const std::function<double(real2)> smooth = [](real2 q) { return std::exp(q.x * q.y); };
  const std::function<double(real2)> disk = [](real2 q) {
    return (q.x - 0.5) * (q.x - 0.5) + (q.y - 0.5) * (q.y - 0.5) < 0.16 ? 1.0 : 0.0;
  };
  struct integrand {
    const char* name;
    const std::function<double(real2)>& f;
    double exact, min_sobol_slope, min_ratio;
  };
  for (const integrand& c : {integrand{"smooth", smooth, smooth_exact, 1.2, 15},
                             integrand{"disk", disk, 0.16 * std::numbers::pi, 0.65, 3}}) {
    double slope[2], at_256[2];
    for (const bool sobol : {false, true}) {
      const double e16 = rms_error(c.f, c.exact, 16, sobol);
      const double e64 = rms_error(c.f, c.exact, 64, sobol);
      const double e256 = rms_error(c.f, c.exact, 256, sobol);
      slope[sobol] = -std::log(e256 / e16) / std::log(16.0);
      at_256[sobol] = e256;
      std::printf("%s %s: rms %.3g %.3g %.3g at 16 64 256 samples, slope -%.2f\n", c.name,
                  sobol ? "sobol" : "rnd", e16, e64, e256, slope[sobol]);
      EXPECT_LT(e64, e16) << c.name;
      EXPECT_LT(e256, e64) << c.name;
    }
    EXPECT_GT(slope[1], c.min_sobol_slope) << c.name;
    EXPECT_LT(slope[0], 0.7) << c.name << ": independent numbers converge as n^-0.5";
    EXPECT_GT(at_256[0] / at_256[1], c.min_ratio) << c.name;
  }
}

}  // namespace
}  // namespace rtvk
