// The view transforms (base/byte_encoding.h, shaders/shared/view_transform.h, docs/color.md):
// known bytes from the published definitions, exposure as a factor of 2^EV, and the integer
// thresholds the GPU mirrors for every per-channel transform. The filmic and AgX bytes come from
// tests/oracle/view_transforms.py, an independent plain-Python implementation of the published
// formulas (its matrices from the primaries, its sigmoid's scales by bisection).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "byte_encoding.h"
#include "sample_sum.h"
#include "view_transform.h"

namespace rtvk {
namespace {

display_encoding vt_encoding(view_transform t, double exposure = 0) {
  return {t, 1, exposure};
}

std::uint8_t vt_byte(view_transform t, double c, double exposure = 0) {
  return encode_color(c, c, c, vt_encoding(t, exposure))[0];
}

TEST(ViewTransform, StandardIsTheSrgbTransferFunction) {
  // IEC 61966-2-1: 12.92 c below 0.0031308, 1.055 c^(1/2.4) - 0.055 above; bytes by the lesson's
  // int(255.999 c): 0.5 -> 0.7354 -> 188, 0.18 -> 0.4614 -> 118.
  EXPECT_EQ(vt_byte(view_transform::standard, 0.5), 188);
  EXPECT_EQ(vt_byte(view_transform::standard, 0.18), 118);
  EXPECT_EQ(vt_byte(view_transform::standard, 0.01), 25);
  EXPECT_EQ(vt_byte(view_transform::standard, 0.001), 3);  // the line: 12.92 * 0.001 = 0.01292
  EXPECT_EQ(vt_byte(view_transform::standard, 0.0031308), 10);
  EXPECT_EQ(vt_byte(view_transform::standard, 1.0), 255);
  EXPECT_EQ(vt_byte(view_transform::standard, 0.0), 0);
  EXPECT_EQ(vt_byte(view_transform::standard, -1.0), 0);
  // The two pieces meet at the boundary (to 1e-4, as the standard's rounded constants do).
  EXPECT_NEAR(srgb_encode(0.0031308), 1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 1e-4);
  EXPECT_DOUBLE_EQ(srgb_encode(0.0031308), 12.92 * 0.0031308);
  EXPECT_DOUBLE_EQ(srgb_encode(0.5), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055);
}

TEST(ViewTransform, LinearAndGammaAreThePowerLaws) {
  for (double c : {0.0, 0.01, 0.18, 0.5, 0.9, 1.0, 2.0}) {
    EXPECT_EQ(vt_byte(view_transform::linear, c), to_byte(c));
    EXPECT_EQ(encode_color(c, c, c, {view_transform::gamma, 2, 0})[1], to_byte(std::sqrt(c)));
    EXPECT_EQ(encode_color(c, c, c, {view_transform::gamma, 2.2, 0})[2],
              to_byte(std::pow(c, 1 / 2.2)));
  }
}

TEST(ViewTransform, FilmicMatchesTheIndependentReference) {
  // python3 tests/oracle/view_transforms.py: Hable's curve, exposure bias 2, white 11.2, sRGB.
  EXPECT_EQ(vt_byte(view_transform::filmic, 0.01), 21);
  EXPECT_EQ(vt_byte(view_transform::filmic, 0.18), 100);
  EXPECT_EQ(vt_byte(view_transform::filmic, 1.0), 187);
  EXPECT_EQ(vt_byte(view_transform::filmic, 4.0), 246);
  EXPECT_EQ(vt_byte(view_transform::filmic, 5.6), 255);  // 2 * 5.6 = W: white
  EXPECT_EQ(vt_byte(view_transform::filmic, 0.0), 0);
}

TEST(ViewTransform, AgxMatchesTheIndependentReference) {
  const display_encoding agx = vt_encoding(view_transform::agx);
  using rgb = std::array<std::uint8_t, 3>;
  // python3 tests/oracle/view_transforms.py. Mid grey stays where sRGB puts it (the sigmoid's
  // pivot is 0.18 and the matrices keep greys), a pure red goes toward white along its hue.
  EXPECT_EQ(encode_color(0.18, 0.18, 0.18, agx), (rgb{118, 118, 118}));
  EXPECT_EQ(encode_color(1, 0, 0, agx), (rgb{218, 66, 30}));
  EXPECT_EQ(encode_color(4, 1, 0.25, agx), (rgb{241, 201, 171}));
  EXPECT_EQ(encode_color(0.02, 0.05, 0.3, agx), (rgb{25, 72, 148}));
  EXPECT_EQ(encode_color(16, 16, 16, agx), (rgb{255, 255, 255}));
  EXPECT_EQ(encode_color(0, 0, 0, agx), (rgb{0, 0, 0}));
  // The sigmoid passes through its ends and its pivot with slope 2.4.
  EXPECT_NEAR(agx_sigmoid(0.0), 0.0, 1e-12);
  EXPECT_NEAR(agx_sigmoid(1.0), 1.0, 1e-12);
  const double xp = 10 / 16.5, h = 1e-6;
  EXPECT_NEAR(agx_sigmoid(xp), std::pow(0.18, 1 / 2.4), 1e-12);
  EXPECT_NEAR((agx_sigmoid(xp + h) - agx_sigmoid(xp - h)) / (2 * h), 2.4, 1e-6);
}

TEST(ViewTransform, OneStopOfExposureIsTwiceTheLight) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> light(0.0, 3.0);
  for (view_transform t : {view_transform::standard, view_transform::filmic, view_transform::agx,
                           view_transform::linear, view_transform::gamma}) {
    for (int i = 0; i < 2000; ++i) {
      const double r = light(rng), g = light(rng), b = light(rng);
      ASSERT_EQ(encode_color(r, g, b, vt_encoding(t, 1)),
                encode_color(2 * r, 2 * g, 2 * b, vt_encoding(t)))
          << view_transform_name(t) << " " << r << "," << g << "," << b;
      ASSERT_EQ(encode_color(r, g, b, vt_encoding(t, -2)),
                encode_color(r / 4, g / 4, b / 4, vt_encoding(t)));
    }
  }
  // 0.09 at +1 EV is 0.18's 118 in sRGB.
  EXPECT_EQ(vt_byte(view_transform::standard, 0.09, 1), 118);
}

TEST(ViewTransform, ThresholdsEncodeEveryPerChannelTransformExactly) {
  std::mt19937_64 rng(4444);
  for (view_transform t : {view_transform::standard, view_transform::filmic, view_transform::linear,
                           view_transform::gamma}) {
    for (double ev : {0.0, 1.5, -3.0, 16.0, -16.0}) {
      for (int f : {42, 20}) {
        const display_encoding e{t, 2.2, ev};
        const byte_thresholds th = make_byte_thresholds(e, f);
        for (int k = 1; k < 256; ++k) ASSERT_LE(th[k - 1], th[k]);
        ASSERT_LT(th[255], std::uint64_t(1) << 63);
        for (int i = 0; i < 3000; ++i) {
          const std::uint32_t n = 1 + std::uint32_t(rng() % (1u << 20));
          // Means up to past the byte 255's threshold, and exactly on thresholds.
          const std::uint64_t mean_fixed =
              i % 4 == 0 ? th[1 + rng() % 255] : rng() % (th[255] + th[255] / 8 + 1);
          const exact_sum sum = exact_sum(mean_fixed) * n + rng() % n;
          const std::uint8_t want = to_byte(encode_channel(std::ldexp(double(mean_fixed), -f), e));
          ASSERT_EQ(encode_sum(sum, n, th), want)
              << view_transform_name(t) << " EV " << ev << " F " << f << " mean " << mean_fixed;
        }
      }
    }
  }
  // The books' power law at 0 EV keeps the thresholds it always had.
  EXPECT_EQ(make_byte_thresholds(display_encoding{view_transform::gamma, 2, 0}, 42),
            make_byte_thresholds(2.0, 42));
}

TEST(ViewTransform, NamesRoundTrip) {
  for (view_transform t : {view_transform::standard, view_transform::filmic, view_transform::agx,
                           view_transform::linear, view_transform::gamma})
    EXPECT_EQ(view_transform_from_name(view_transform_name(t)), t);
  EXPECT_FALSE(view_transform_from_name("Filmic"));
  EXPECT_FALSE(view_transform_from_name(""));
}

}  // namespace
}  // namespace rtvk
