#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "random.h"
#include "vec3.h"

namespace rtvk {
namespace {

// Known answers computed by an independent Python implementation of the same hash chain.
TEST(Random, KnownAnswers) {
  EXPECT_EQ(hash32(0), 0u);
  EXPECT_EQ(hash32(1), 0x688990c0u);
  EXPECT_EQ(hash32(2), 0xd1132181u);
  EXPECT_EQ(hash32(0xdeadbeef), 0xe628c683u);
  EXPECT_EQ(random_bits(0, 0, 0, 0, 0), 0x41f39e5eu);
  EXPECT_EQ(random_bits(0, 1, 0, 0, 0), 0x13f967ebu);
  EXPECT_EQ(random_bits(7, 12345, 3, 2, 1), 0xe50283d9u);
  EXPECT_EQ(random_bits(0xffffffff, 0xffffffff, 99, 50, 15), 0xbea77bcdu);
  EXPECT_EQ(random_float(7, 12345, 3, 2, 1), 0.8945695757865906f);
}

TEST(Random, StreamsDrawTheNumbersOfTheirCounters) {
  // Each field lands on its own counter: the known answer above is (seed 7, pixel 12345,
  // sample 3, bounce 2, dimension 1), reached here through at_bounce from bounce 0.
  const random_stream a = pixel_sample_stream(7, 12345, 3);
  EXPECT_EQ(rnd(at_bounce(a, 2), 1), 0.8945695757865906f);
  EXPECT_NE(rnd(a, 1), rnd(at_bounce(a, 2), 1));  // the bounce is a counter too
  std::set<float> seen;                           // neighbouring counters give unrelated numbers
  for (std::uint32_t p = 0; p < 8; ++p)
    for (std::uint32_t s = 0; s < 8; ++s)
      for (std::uint32_t d = 0; d < 4; ++d) seen.insert(random_float(0, p, s, 1, d));
  EXPECT_EQ(seen.size(), 256u);
}

TEST(Random, UniformInUnitInterval) {
  const int n = 200000;
  double sum = 0, sum_sq = 0;
  int below_tenth = 0;
  for (int i = 0; i < n; ++i) {
    const double x = random_float(42, std::uint32_t(i), 0, 0, 0);
    ASSERT_GE(x, 0.0);
    ASSERT_LT(x, 1.0);
    sum += x;
    sum_sq += x * x;
    below_tenth += x < 0.1;
  }
  // Uniform: mean 1/2 (sd of the mean 0.00065), second moment 1/3, P(x < 0.1) = 0.1.
  EXPECT_NEAR(sum / n, 0.5, 0.004);
  EXPECT_NEAR(sum_sq / n, 1.0 / 3.0, 0.004);
  EXPECT_NEAR(below_tenth / double(n), 0.1, 0.004);
}

TEST(Random, DirectionSamplers) {
  vec3 mean(0);
  for (std::uint32_t i = 0; i < 20000; ++i) {
    const random_stream s = at_bounce(pixel_sample_stream(1, i, 0), 1);
    const vec3 u = random_unit_vector(rnd(s, 0), rnd(s, 1));
    ASSERT_NEAR(glm::length(u), 1.0, 1e-12);
    mean += u;
    ASSERT_LE(glm::length(random_in_unit_sphere(rnd(s, 0), rnd(s, 1), rnd(s, 2))), 1.0 + 1e-12);
    ASSERT_LE(glm::length(random_in_unit_disk(rnd(s, 0), rnd(s, 1))), 1.0 + 1e-12);
  }
  mean /= 20000.0;
  EXPECT_LT(glm::length(mean), 0.03);  // no preferred direction
}

// The directions' angles come from polynomials, not libm: they must be cos and sin of 2 pi b to
// double precision everywhere in [0, 1), quarter-turn boundaries and both ends included (every
// random number is a multiple of 2^-24, so all of them are checked at the boundaries' sides).
TEST(Random, TurnCosSinIsCosAndSinOfTheTurnToDoublePrecision) {
  double worst = 0;
  const auto check = [&](double b) {
    const glm::dvec2 cs = turn_cos_sin(b);
    worst = std::max(
        {worst, std::abs(cs.x - std::cos(2 * pi * b)), std::abs(cs.y - std::sin(2 * pi * b))});
  };
  for (std::uint32_t k = 0; k < (1u << 24); k += 97) check(k * 0x1p-24);
  for (const double edge : {0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0})
    for (int d = -8; d <= 8; ++d)
      if (edge + d * 0x1p-24 >= 0 && edge + d * 0x1p-24 < 1) check(edge + d * 0x1p-24);
  EXPECT_LE(worst, 1e-15);  // 2 pi b itself rounds by ~4e-16 in the reference
}

}  // namespace
}  // namespace rtvk
