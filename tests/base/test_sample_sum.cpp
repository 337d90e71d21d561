// Exact sums and their 8-bit encoding (base/sample_sum.h, base/byte_encoding.h): the integer
// encoding the GPU mirrors must be the lesson's to_byte of the gamma-encoded mean.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "byte_encoding.h"
#include "sample_sum.h"

namespace rtvk {
namespace {

TEST(SampleSum, ExponentLeavesRoomForAMillionSamplesOfTwiceTheBrightest) {
  EXPECT_EQ(sum_exponent(1.0), 42);
  EXPECT_EQ(sum_exponent(0.5), 42);  // the normal material's 1 still has to fit
  EXPECT_EQ(sum_exponent(3.0), 40);
  for (double brightest : {1.0, 3.0, 1000.0, 1e30}) {
    const int f = sum_exponent(brightest);
    EXPECT_GE(sum_sample_limit(f), 2 * brightest) << brightest;
    // 2^20 samples at the limit fit 63 bits.
    EXPECT_LE(std::log2(sum_sample_limit(f)) + f + max_sum_samples_log2, 63.0) << brightest;
  }
}

TEST(SampleSum, ToFixedIsExactDownToTheLastFractionalBit) {
  EXPECT_EQ(to_fixed(1.0f, 42), std::uint64_t(1) << 42);
  EXPECT_EQ(to_fixed(0.75f, 42), std::uint64_t(3) << 40);
  EXPECT_EQ(to_fixed(0x1p-43f, 42), 0u);  // below 2^-F: dropped
  EXPECT_EQ(to_fixed(0x1.8p-42f, 42), 1u);
  EXPECT_EQ(to_fixed(-0.5f, 42), 0u);
  // Every bit of a float in [2^-18, 2) survives: 24 bits of mantissa within 42 fractional bits.
  const float c = 0x1.234566p-1f;
  EXPECT_EQ(std::ldexp(double(to_fixed(c, 42)), -42), double(c));
}

TEST(ByteEncoding, EncodeSumIsTheLessonsByteOfTheMeanForEveryGamma) {
  std::mt19937_64 rng(1234);
  for (double gamma : {1.0, 2.0, 2.2}) {
    for (int f : {42, 40, 10}) {
      const byte_thresholds t = make_byte_thresholds(gamma, f);
      EXPECT_EQ(t[0], 0u);
      for (int k = 1; k < 256; ++k) ASSERT_LE(t[k - 1], t[k]) << "gamma " << gamma << " byte " << k;
      for (int i = 0; i < 20000; ++i) {
        const std::uint32_t n = 1 + std::uint32_t(rng() % (1u << 20));
        // Means around [0, 1.1), and exactly on some thresholds, where rounding would show.
        const std::uint64_t mean_fixed =
            i % 4 == 0 ? t[1 + rng() % 255] : rng() % (std::uint64_t(11) << f) / 10;
        const std::uint64_t sum = mean_fixed * n + rng() % n;  // floor(sum / n) == mean_fixed
        const std::uint8_t want = to_byte(encode_gamma(std::ldexp(double(mean_fixed), -f), gamma));
        ASSERT_EQ(encode_sum(sum, n, t), want)
            << "gamma " << gamma << ", F " << f << ", sum " << sum << ", samples " << n;
      }
    }
  }
  EXPECT_EQ(encode_sum(12345, 0, make_byte_thresholds(1, 42)), 0);  // no samples: black
}

}  // namespace
}  // namespace rtvk
