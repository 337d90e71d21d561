#include <gtest/gtest.h>

#include <cmath>

#include "shading.h"

namespace rtvk {
namespace {

hit_record hit_at_origin(vec3 normal, bool front_face = true) {
  hit_record rec{};
  rec.p = point3(0, 0, 0);
  rec.normal = normal;
  rec.front_face = front_face;
  rec.offset = 1e-6;
  return rec;
}

random_stream stream(std::uint32_t i) {
  return at_bounce(pixel_sample_stream(9, i, 0), 1);
}

TEST(Lambertian, ScattersIntoTheHemisphereAroundTheNormal) {
  const material m{material_type::lambertian, color(0.2, 0.4, 0.6), 0, 1.5};
  const hit_record rec = hit_at_origin(vec3(0, 1, 0));
  double mean_cos = 0;
  for (std::uint32_t i = 0; i < 20000; ++i) {
    color attenuation;
    ray out;
    ASSERT_TRUE(scatter(m, ray(point3(0, 1, 0), vec3(0, -1, 0)), rec, stream(i), attenuation, out));
    ASSERT_GE(glm::dot(out.direction, rec.normal), 0.0);
    ASSERT_GT(out.origin.y, 0.0);  // leaves from just above the surface
    EXPECT_EQ(attenuation, m.albedo);
    mean_cos += glm::dot(unit_vector(out.direction), rec.normal);
  }
  // Cosine-weighted about the normal: E[cos theta] = 2/3.
  EXPECT_NEAR(mean_cos / 20000, 2.0 / 3.0, 0.01);
}

TEST(Metal, MirrorsWithoutFuzz) {
  const material m{material_type::metal, color(0.9), 0.0, 1.5};
  color attenuation;
  ray out;
  ASSERT_TRUE(scatter(m, ray(point3(-1, 1, 0), vec3(1, -1, 0)), hit_at_origin(vec3(0, 1, 0)),
                      stream(0), attenuation, out));
  const vec3 d = unit_vector(out.direction);
  EXPECT_NEAR(d.x, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(d.y, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(d.z, 0.0, 1e-12);
  EXPECT_EQ(attenuation, color(0.9));
}

TEST(Metal, FuzzPerturbsAndAbsorbsBelowTheSurface) {
  const material m{material_type::metal, color(1), 1.0, 1.5};
  int absorbed = 0;
  // A grazing incoming ray with full fuzz: some reflections point into the surface.
  for (std::uint32_t i = 0; i < 2000; ++i) {
    color attenuation;
    ray out;
    const bool kept = scatter(m, ray(point3(-1, 0.01, 0), vec3(1, -0.01, 0)),
                              hit_at_origin(vec3(0, 1, 0)), stream(i), attenuation, out);
    absorbed += !kept;
    if (kept) {
      EXPECT_GT(glm::dot(out.direction, vec3(0, 1, 0)), 0.0);
    }
  }
  EXPECT_GT(absorbed, 100);
  EXPECT_LT(absorbed, 1900);
}

TEST(Dielectric, RefractionObeysSnellsLaw) {
  const double ir = 1.5;
  const vec3 n(0, 1, 0);
  for (double angle_deg : {0.0, 10.0, 30.0, 60.0, 80.0}) {
    const double a = angle_deg * pi / 180;
    const vec3 in(std::sin(a), -std::cos(a), 0);  // unit, into the surface
    const vec3 out = refract_dir(in, n, 1.0 / ir);
    const double sin_t = std::abs(unit_vector(out).x);
    EXPECT_NEAR(sin_t, std::sin(a) / ir, 1e-12) << angle_deg;  // n1 sin(i) = n2 sin(t)
    EXPECT_NEAR(glm::length(out), 1.0, 1e-12);
    EXPECT_LT(out.y, 0);  // continues into the glass
  }
}

TEST(Dielectric, TotalInternalReflection) {
  // From inside glass (back face) at 60 degrees: 1.5 * sin(60) = 1.3 > 1, so it must reflect,
  // whatever the random number.
  const material m{material_type::dielectric, color(1), 0, 1.5};
  const double a = 60 * pi / 180;
  const vec3 in(std::sin(a), std::cos(a), 0);  // travelling up toward the surface from inside
  for (std::uint32_t i = 0; i < 200; ++i) {
    color attenuation;
    ray out;
    ASSERT_TRUE(scatter(m, ray(point3(0, -1, 0), in), hit_at_origin(vec3(0, -1, 0), false),
                        stream(i), attenuation, out));
    EXPECT_NEAR(unit_vector(out.direction).y, -std::cos(a), 1e-12);  // mirrored back down
    EXPECT_EQ(attenuation, color(1, 1, 1));
  }
}

TEST(Dielectric, SchlickAtNormalAndGrazingIncidence) {
  EXPECT_NEAR(schlick_reflectance(1.0, 1.5), 0.04, 1e-12);  // ((1 - 1.5) / (1 + 1.5))^2
  EXPECT_NEAR(schlick_reflectance(0.0, 1.5), 1.0, 1e-12);
  EXPECT_NEAR(schlick_reflectance(1.0, 1.0 / 1.5), 0.04, 1e-12);
  // In between, monotonic.
  EXPECT_LT(schlick_reflectance(0.8, 1.5), schlick_reflectance(0.3, 1.5));
}

TEST(Dielectric, ReflectsAboutTheSchlickFraction) {
  // Head-on: about 4% of rays reflect.
  const material m{material_type::dielectric, color(1), 0, 1.5};
  int reflected = 0;
  const int n = 20000;
  for (std::uint32_t i = 0; i < std::uint32_t(n); ++i) {
    color attenuation;
    ray out;
    scatter(m, ray(point3(0, 1, 0), vec3(0, -1, 0)), hit_at_origin(vec3(0, 1, 0)), stream(i),
            attenuation, out);
    reflected += out.direction.y > 0;
  }
  EXPECT_NEAR(reflected / double(n), 0.04, 0.006);
}

TEST(NormalMaterial, DoesNotScatter) {
  color attenuation;
  ray out;
  EXPECT_FALSE(scatter(material{}, ray(point3(0, 1, 0), vec3(0, -1, 0)),
                       hit_at_origin(vec3(0, 1, 0)), stream(0), attenuation, out));
}

}  // namespace
}  // namespace rtvk
