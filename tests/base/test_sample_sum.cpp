// Exact sums and their 8-bit encoding (base/sample_sum.h, base/byte_encoding.h): the integer
// encoding the GPU mirrors must be the lesson's to_byte of the gamma-encoded mean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "byte_encoding.h"
#include "sample_sum.h"

namespace rtvk {
namespace {

TEST(SampleSum, FortyTwoFractionalBitsAndRoomForAMillionSamplesOfTwiceTheBrightest) {
  EXPECT_EQ(sum_exponent(1.0), 42);
  EXPECT_EQ(sum_exponent(0.5), 42);  // the normal material's 1 still has to fit
  EXPECT_EQ(sum_exponent(3.0), 42);
  EXPECT_EQ(sum_exponent(1e6), 42);  // a lamp's brightness keeps every fractional bit
  EXPECT_EQ(sum_exponent(0x1p32), 42);
  EXPECT_EQ(sum_exponent(0x1p33), 41);
  EXPECT_EQ(sum_sample_limit(42), 0x1p33);
  for (double brightest : {1.0, 3.0, 1000.0, 1e6, 1e12, 1e30}) {
    const int f = sum_exponent(brightest);
    EXPECT_GE(sum_sample_limit(f), 2 * brightest) << brightest;
    // 2^20 samples at the limit fit 95 bits, so a sum never reaches the 96th.
    EXPECT_LE(std::log2(sum_sample_limit(f)) + f + max_sum_samples_log2, 95.0) << brightest;
  }
}

TEST(SampleSum, ToFixedIsExactDownToTheLastFractionalBit) {
  EXPECT_TRUE(to_fixed(1.0f, 42) == exact_sum(1) << 42);
  EXPECT_TRUE(to_fixed(0.75f, 42) == exact_sum(3) << 40);
  EXPECT_TRUE(to_fixed(0x1p-43f, 42) == 0);  // below 2^-F: dropped
  EXPECT_TRUE(to_fixed(0x1.8p-42f, 42) == 1);
  EXPECT_TRUE(to_fixed(-0.5f, 42) == 0);
  EXPECT_TRUE(to_fixed(1e6f, 42) == exact_sum(1e6 * 0x1p42));  // past 64 bits once summed
  EXPECT_TRUE(to_fixed(0x1p33f, 42) == exact_sum(1) << 75);    // the limit itself is added
  // Past the limit, and infinity: overflow (the render fails), nothing added.
  EXPECT_TRUE(sum_overflows(0x1.000002p33f, 42) && to_fixed(0x1.000002p33f, 42) == 0);
  // Infinities are dropped (the render counts them), not overflows that fail the render.
  EXPECT_FALSE(sum_overflows(std::numeric_limits<float>::infinity(), 42));
  EXPECT_TRUE(to_fixed(std::numeric_limits<float>::infinity(), 42) == 0);
  EXPECT_FALSE(sum_overflows(std::numeric_limits<float>::quiet_NaN(), 42));
  EXPECT_FALSE(sum_overflows(0x1p33f, 42));
  // Every bit of a float in [2^-18, 2) survives: 24 bits of mantissa within 42 fractional bits.
  const float c = 0x1.234566p-1f;
  EXPECT_EQ(std::ldexp(double(to_fixed(c, 42)), -42), double(c));
}

// Samples of 10^6 and 10^-6 mixed, in any order and any batching: the same sum, and the mean
// keeps both (a 64-bit sum with F fitted to 10^6 would keep 22 fractional bits: 10^-6 would add
// 4 units of 2^-22, 4.6% short).
TEST(SampleSum, BrightAndDimSamplesMixedAddTheSameInAnyOrderAndKeepBoth) {
  std::vector<float> samples;
  for (int i = 0; i < 1000; ++i) samples.push_back(i % 10 == 3 ? 1e6f : 1e-6f);
  const int f = sum_exponent(1e6);
  const auto sum_of = [&](const std::vector<float>& v) {
    exact_sum s = 0;
    for (float c : v) s += to_fixed(c, f);
    return s;
  };
  const exact_sum want = sum_of(samples);
  EXPECT_GT(want >> 64, 0u);  // a thousand samples of 10^6 are past 64 bits at F = 42
  std::mt19937 gen(5);
  for (int k = 0; k < 10; ++k) {
    std::shuffle(samples.begin(), samples.end(), gen);
    EXPECT_TRUE(sum_of(samples) == want);
  }
  const double mean = sum_mean(want, 1000, f);
  const double exact = (100 * double(1e6f) + 900 * double(1e-6f)) / 1000;
  EXPECT_NEAR(mean, exact, 1e-15 * exact);
  // The dim samples alone: every one of them is kept to 2^-42.
  EXPECT_NEAR(sum_mean(900 * to_fixed(1e-6f, f), 900, f), double(1e-6f), 0x1p-42);
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
        const exact_sum sum = exact_sum(mean_fixed) * n + rng() % n;  // floor(sum / n) == mean
        const std::uint8_t want = to_byte(encode_gamma(std::ldexp(double(mean_fixed), -f), gamma));
        ASSERT_EQ(encode_sum(sum, n, t), want)
            << "gamma " << gamma << ", F " << f << ", sum " << double(sum) << ", samples " << n;
      }
    }
  }
  EXPECT_EQ(encode_sum(12345, 0, make_byte_thresholds(1, 42)), 0);  // no samples: black
  // A sum past 64 bits (a lamp's samples) is a mean past 1: white.
  EXPECT_EQ(encode_sum(exact_sum(1) << 70, 1u << 20, make_byte_thresholds(2, 42)), 255);
  EXPECT_EQ(encode_sum((exact_sum(1) << 64) - 1, 1u << 20, make_byte_thresholds(2, 42)), 255);
}

}  // namespace
}  // namespace rtvk
