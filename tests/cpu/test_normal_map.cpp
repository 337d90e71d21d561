// shaders/shared/pbr/normal_map.h in its C++ compilation: the mapped normal in the hit's tangent
// frame, and the no-leak rule (docs/materials.md, "Normal maps").
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "normal_map.h"
#include "vec3.h"

namespace rtvk {
namespace {

// A hit with normal N and tangent T (w the handedness), the frame tilted off the axes.
hit_record normal_map_hit(double w = 1) {
  hit_record rec{};
  rec.normal = glm::normalize(vec3(0.2, 0.3, 1));
  const vec3 t = glm::normalize(vec3(1, -0.4, 0));
  rec.tangent = glm::dvec4(glm::normalize(t - glm::dot(t, rec.normal) * rec.normal), w);
  rec.front_face = true;
  return rec;
}

// Exactly: bit for bit, for normals whose rounded length is not exactly 1 too.
TEST(NormalMap, AFlatTexelGivesTheNormalExactly) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 100; ++i) {
    hit_record rec = normal_map_hit();
    rec.normal = glm::normalize(vec3(u(gen), u(gen), 1));
    const vec3 wo = rec.normal;
    for (const double scale : {1.0, 0.3, 2.0}) {
      const vec3 n = normal_mapped(rec, vec3(0.5, 0.5, 1), scale, wo);
      ASSERT_EQ(n, rec.normal) << i;
    }
  }
}

TEST(NormalMap, WithoutTangentsTheNormalIsUnchanged) {
  hit_record rec = normal_map_hit();
  rec.tangent = glm::dvec4(0);
  EXPECT_EQ(normal_mapped(rec, vec3(0.9, 0.1, 0.6), 1, rec.normal), rec.normal);
}

// A texel of (0.75, 0.5, 1): tangent space (0.5 scale, 0, 1) made unit, in the frame (T, B, N)
// with B = cross(N, T) * w; the handedness turns the y part.
TEST(NormalMap, ATiltedTexelGivesTheAnalyticNormal) {
  for (const double w : {1.0, -1.0}) {
    const hit_record rec = normal_map_hit(w);
    const vec3 T(rec.tangent), N = rec.normal, B = w * glm::cross(N, T);
    const vec3 wo = N;
    const double scale = 0.8;
    const vec3 ts = glm::normalize(vec3(0.5 * scale, -0.5 * scale, 1));
    const vec3 want = ts.x * T + ts.y * B + ts.z * N;
    const vec3 got = normal_mapped(rec, vec3(0.75, 0.25, 1), scale, wo);
    EXPECT_NEAR(glm::distance(got, want), 0, 1e-12);
    EXPECT_NEAR(glm::length(got), 1, 1e-12);
  }
}

// Random texels and grazing viewers: the viewer always sees the mapped normal at a cosine of at
// least the margin; where it already did, the normal is the map's (untouched); where not, the
// result leans from N no further than the map's normal, and reaches the margin exactly.
TEST(NormalMap, TheNoLeakRuleKeepsTheViewerAboveTheShadingPlane) {
  std::mt19937 gen(45);
  std::uniform_real_distribution<double> u01(0, 1);
  int bent = 0, grazing = 0;
  for (int i = 0; i < 20000; ++i) {
    const hit_record rec = normal_map_hit(u01(gen) < 0.5 ? 1 : -1);
    const vec3 N = rec.normal, T(rec.tangent), B = rec.tangent.w * glm::cross(N, T);
    const vec3 texel(u01(gen), u01(gen), u01(gen));
    const double scale = 2 * u01(gen);
    // wo from near the horizon (cos 0 to 0.05) to overhead, any azimuth.
    const double c = i % 2 ? 0.05 * u01(gen) : u01(gen), phi = 2 * pi * u01(gen);
    const double s = std::sqrt(1 - c * c);
    const vec3 wo = s * std::cos(phi) * T + s * std::sin(phi) * B + c * N;
    const vec3 n = normal_mapped(rec, texel, scale, wo);
    ASSERT_NEAR(glm::length(n), 1, 1e-9);
    ASSERT_GE(glm::dot(wo, n), normal_map_margin - 1e-12) << i;
    const vec3 ts = (2.0 * texel - 1.0) * vec3(scale, scale, 1);
    const vec3 raw = glm::normalize(ts.x * T + ts.y * B + ts.z * N);
    if (glm::dot(wo, raw) >= normal_map_margin) {
      EXPECT_NEAR(glm::distance(n, raw), 0, 1e-12);
    } else {
      EXPECT_NEAR(glm::dot(wo, n), normal_map_margin, 1e-9);
      if (glm::dot(wo, N) >= normal_map_margin) {
        EXPECT_GE(glm::dot(n, N), glm::dot(raw, N) - 1e-12);  // toward N, not past it
        ++bent;
      } else {
        ++grazing;
      }
    }
  }
  EXPECT_GT(bent, 1000);  // both branches ran
  EXPECT_GT(grazing, 1000);
}

}  // namespace
}  // namespace rtvk
