// punctual.h's known answers, in the CPU's double compilation: a point light's inverse square, a
// spot's falloff against KHR_lights_punctual's reference formula, a directional light's
// irradiance, and a sun's cone sampler (its density integrates to 1 over the sphere, its samples
// stay in the cone, and the irradiance they give a surface facing it integrates to E).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "light_sources.h"
#include "punctual.h"

namespace rtvk {
namespace {

punctual_table punctual_table_of(const std::vector<punctual_record>& records) {
  return {records.data(), std::uint32_t(records.size())};
}

constexpr double deg = std::numbers::pi / 180;

light_sample sample_one(const punctual_light& l, const vec3& p, glm::dvec2 u = {0.5, 0.5}) {
  const std::vector<punctual_record> r = punctual_records({l});
  return punctual_sample(punctual_table_of(r), 0, p, u);
}

TEST(PunctualKernel, PointLightFallsOffAsTheInverseSquare) {
  punctual_light l;
  l.position = {1, 2, 3};
  l.tint = {1, 0.5, 0.25};
  l.intensity = 40;  // candela
  for (const double d : {0.5, 1.0, 2.0, 7.0, 100.0}) {
    const vec3 p = l.position + d * glm::normalize(vec3(1, -2, 2));
    const light_sample s = sample_one(l, p);
    EXPECT_TRUE(s.delta);
    EXPECT_EQ(s.pdf, 1.0);
    EXPECT_NEAR(s.distance, d, 1e-12 * d);
    EXPECT_NEAR(glm::length(s.wi - glm::normalize(l.position - p)), 0, 1e-12);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.radiance[c], 40 * l.tint[c] / (d * d), 1e-12 / d);
  }
}

// KHR_lights_punctual's README: scale = 1 / max(0.001, cos(inner) - cos(outer)), offset =
// -cos(outer) * scale, attenuation = saturate(cd * scale + offset)^2.
double gltf_spot(double angle, double inner, double outer) {
  const double scale = 1 / std::max(0.001, std::cos(inner) - std::cos(outer));
  const double a = std::clamp(std::cos(angle) * scale - std::cos(outer) * scale, 0.0, 1.0);
  return a * a;
}

TEST(PunctualKernel, SpotFalloffIsTheGltfReferenceFormula) {
  punctual_light l;
  l.kind = punctual_kind::spot;
  l.position = {0, 3, 0};
  l.direction = {0, -1, 0};
  l.intensity = 9;
  l.inner_cone = 20;
  l.outer_cone = 40;
  // Points 3 units from the spot, at angles inside the inner cone, between the cones, on the
  // outer edge and outside it.
  for (const double a : {0.0, 10.0, 19.0, 21.0, 30.0, 39.0, 40.0, 45.0, 90.0, 150.0}) {
    const vec3 p = l.position + 3.0 * vec3(std::sin(a * deg), -std::cos(a * deg), 0);
    const double want = 9 / 9.0 * gltf_spot(a * deg, 20 * deg, 40 * deg);
    const light_sample s = sample_one(l, p);
    EXPECT_NEAR(s.radiance.x, want, 1e-12) << a << " degrees";
    if (a < 20) {
      EXPECT_NEAR(s.radiance.x, 1.0, 1e-12) << a;
    } else if (a >= 40) {
      EXPECT_EQ(s.radiance.x, 0.0) << a;
    } else if (a > 20) {
      EXPECT_TRUE(s.radiance.x > 0 && s.radiance.x < 1) << a;
    }
  }
}

TEST(PunctualKernel, DirectionalLightGivesItsLuxFromInfinity) {
  punctual_light l;
  l.kind = punctual_kind::directional;
  l.direction = {0, -2, 0};  // normalized when recorded
  l.tint = {1, 0.9, 0.8};
  l.intensity = 3;  // lux
  const light_sample s = sample_one(l, {5, -7, 2}, {0.1, 0.9});
  EXPECT_TRUE(s.delta);
  EXPECT_EQ(s.pdf, 1.0);
  EXPECT_EQ(s.distance, light_at_infinity);
  EXPECT_EQ(s.wi, vec3(0, 1, 0));
  EXPECT_EQ(s.radiance, 3.0 * l.tint);  // lux times color, no other factor
  const std::vector<punctual_record> r = punctual_records({l});
  EXPECT_EQ(sun_radiance(punctual_table_of(r), vec3(0, 1, 0)), vec3(0));  // a delta light: unseen
  EXPECT_EQ(sun_pdf(punctual_table_of(r), 0, vec3(0, 1, 0)), 0.0);
}

punctual_light sun(double diameter) {
  punctual_light l;
  l.kind = punctual_kind::directional;
  l.direction = glm::normalize(vec3(1, -3, 0.5));
  l.tint = {1, 0.5, 0.25};
  l.intensity = 5;
  l.angular_diameter = diameter;
  return l;
}

TEST(PunctualKernel, SunSamplesStayInItsConeAndItsDensityIsOneOverTheCone) {
  for (const double diameter : {0.53, 10.0, 120.0}) {
    const std::vector<punctual_record> r = punctual_records({sun(diameter)});
    const punctual_table t = punctual_table_of(r);
    const vec3 w = -r[0].direction;
    const double cos_max = std::cos(0.5 * diameter * deg);
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<double> u01;
    for (int i = 0; i < 2000; ++i) {
      const light_sample s = punctual_sample(t, 0, vec3(0), {u01(gen), u01(gen)});
      ASSERT_FALSE(s.delta);
      ASSERT_NEAR(glm::length(s.wi), 1, 1e-12);
      ASSERT_GE(glm::dot(s.wi, w), cos_max - 1e-12) << diameter;
      ASSERT_NEAR(s.pdf, 1 / (2 * std::numbers::pi * (1 - cos_max)), 1e-9 * s.pdf);
      ASSERT_EQ(sun_pdf(t, 0, s.wi), s.pdf);  // what it drew, it finds
      ASSERT_EQ(sun_radiance(t, s.wi), s.radiance);
    }
  }
}

// Uniform directions over the sphere: the mean of pdf / (1 / 4 pi) is 1 (the density integrates
// to 1), within 4 standard errors.
TEST(PunctualKernel, SunDensityIntegratesToOneOverTheSphere) {
  const std::vector<punctual_record> r = punctual_records({sun(60)});
  const punctual_table t = punctual_table_of(r);
  std::mt19937_64 gen(3);
  std::normal_distribution<double> normal;
  const int n = 400000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const vec3 d = glm::normalize(vec3(normal(gen), normal(gen), normal(gen)));
    const double f = sun_pdf(t, 0, d) * 4 * std::numbers::pi;
    sum += f;
    sum2 += f * f;
  }
  const double mean = sum / n, error = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, 1.0, 4 * error);
  EXPECT_LT(error, 0.01);
}

// A surface facing the sun receives E: the estimate L cos(theta) / pdf over its samples.
TEST(PunctualKernel, SunIrradianceOnAFacingSurfaceIsItsLux) {
  for (const double diameter : {0.53, 30.0, 170.0}) {
    const std::vector<punctual_record> r = punctual_records({sun(diameter)});
    const punctual_table t = punctual_table_of(r);
    const vec3 n = -r[0].direction;
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<double> u01;
    const int count = 100000;
    glm::dvec3 sum(0), sum2(0);
    for (int i = 0; i < count; ++i) {
      const light_sample s = punctual_sample(t, 0, vec3(1, 2, 3), {u01(gen), u01(gen)});
      const glm::dvec3 f = s.radiance * glm::dot(s.wi, n) / s.pdf;
      sum += f;
      sum2 += f * f;
    }
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[c] / count;
      const double error = std::sqrt(std::max(0.0, sum2[c] / count - mean * mean) / count);
      const double want = 5 * sun(diameter).tint[c];
      EXPECT_NEAR(mean, want, 4 * error + 1e-9 * want) << diameter << " channel " << c;
      EXPECT_LT(error, 0.02 * want) << diameter;
    }
  }
}

}  // namespace
}  // namespace rtvk
