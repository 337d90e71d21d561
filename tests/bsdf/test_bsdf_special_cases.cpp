// pbr.h's limits that the book's materials are: a metal of roughness 0 is the book's mirror, and
// a transmissive dielectric of index 1 without specular reflection lets light straight through.
// Both are delta lobes, which the cosine Lambertian that stood in before the model has none of:
// these tests fail on it by design, and hold for the glTF model (both compilations).
#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "bsdf_under_test.h"

namespace rtvk::bsdf_test {
namespace {

class BsdfSpecialCases : public testing::TestWithParam<compilation> {
 protected:
  double tolerance() const { return GetParam() == compilation::double_precision ? 1e-9 : 1e-5; }
};

void expect_delta_to(const bsdf_under_test& bsdf, glm::dvec3 wo, glm::dvec3 want_wi,
                     glm::dvec3 want_weight, double tolerance, const std::string& what) {
  std::mt19937_64 rng(0xde17a);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const bsdf_sample s = bsdf.sample(wo, {uniform(rng), uniform(rng), uniform(rng)});
    ASSERT_TRUE(s.sampled) << what;
    ASSERT_TRUE(s.delta) << what << ": a smooth surface's lobe is a delta";
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(s.wi[c], want_wi[c], tolerance) << what << ", wi[" << c << "]";
      EXPECT_NEAR(s.weight[c], want_weight[c], tolerance) << what << ", weight[" << c << "]";
    }
    EXPECT_NEAR(s.pdf, 1.0, tolerance) << what << ": the only lobe is chosen with probability 1";
  }
  // No non-delta lobe: eval and pdf are zero in every direction, the delta's included.
  for (int k = 0; k < 200; ++k) {
    const double z = 2 * uniform(rng) - 1, phi = 6.283185307179586 * uniform(rng);
    const double r = std::sqrt(1 - z * z);
    const glm::dvec3 wi(r * std::cos(phi), r * std::sin(phi), z);
    EXPECT_EQ(bsdf.pdf(wo, wi), 0.0) << what;
    EXPECT_EQ(bsdf.eval(wo, wi), glm::dvec3(0.0)) << what;
  }
  EXPECT_EQ(bsdf.pdf(wo, want_wi), 0.0) << what;
}

// Roughness 0, metallic 1: pbr_sample returns the mirror direction (wo reflected about z) as a
// delta sample whose weight is the base color (Schlick's Fresnel with F0 = base color), as the
// book's metal without fuzz is, at every angle.
TEST_P(BsdfSpecialCases, ARoughnessZeroMetalIsTheMirror) {
  const glm::vec3 base(0.9f, 0.6f, 0.3f);
  const auto bsdf = bsdf_of(GetParam(), pbr_material(base, 1.0f, 0.0f));
  for (double theta : {0.0, 30.0, 60.0, 85.0}) {
    const glm::dvec3 wo = wo_at(theta);
    const glm::dvec3 mirror(-wo.x, -wo.y, wo.z);
    // Schlick: F = F0 + (1 - F0)(1 - cos)^5; at normal incidence the base color itself.
    const double s5 = std::pow(1 - wo.z, 5);
    const glm::dvec3 f = glm::dvec3(base) + (1.0 - glm::dvec3(base)) * s5;
    expect_delta_to(*bsdf, wo, mirror, theta == 0 ? glm::dvec3(base) : f,
                    theta == 0 ? tolerance() : 1e-3 + tolerance(),
                    "metal roughness 0 theta " + std::to_string(int(theta)));
  }
}

// Transmission 1, index 1, roughness 0, metallic 0, specular 0: nothing reflects and nothing
// bends, so wi = -wo and the weight is the base color (the transmission's tint), thin or not.
TEST_P(BsdfSpecialCases, AtIndexOneTransmissionPassesStraightThrough) {
  const glm::vec3 base(0.9f, 0.6f, 0.3f);
  for (unsigned thin : {1u, 0u}) {
    gpu::pbr_probe_entry m = pbr_material(base, 0.0f, 0.0f);
    m.transmission = 1.0f;
    m.eta = 1.0f;
    m.specular = 0.0f;
    m.thin = thin;
    const auto bsdf = bsdf_of(GetParam(), m);
    for (double theta : {0.0, 30.0, 60.0, 85.0}) {
      const glm::dvec3 wo = wo_at(theta);
      expect_delta_to(
          *bsdf, wo, -wo, glm::dvec3(base), tolerance(),
          std::string(thin ? "thin" : "solid") + " theta " + std::to_string(int(theta)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Compilations, BsdfSpecialCases,
                         testing::Values(compilation::double_precision,
                                         compilation::single_precision),
                         [](const testing::TestParamInfo<compilation>& info) {
                           return std::string(name_of(info.param));
                         });

}  // namespace
}  // namespace rtvk::bsdf_test
