// pbr.h's model against answers known without it: GGX's normalization and Smith's masking in
// closed form, the visible normals' density, the compensation tables against a fresh
// integration, the special cases the issue names (the book's mirror, straight-through
// transmission), white furnaces and the energy bound. bsdftests' suite (chi-square, density
// integrals, reciprocity) is the statistical half.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "pbr.h"

namespace rtvk {
namespace {

real3 model_dir(double cos_theta, double phi) {
  const double s = std::sqrt(1.0 - cos_theta * cos_theta);
  return {s * std::cos(phi), s * std::sin(phi), cos_theta};
}

// The integral of D(h) h.z over the hemisphere, by a midpoint rule in theta.
double model_d_cos_integral(double alpha) {
  const int n = 400000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double theta = (k + 0.5) / n * (pi / 2);
    const real3 h = model_dir(std::cos(theta), 0.0);
    sum += ggx_d(h, alpha) * h.z * std::sin(theta);
  }
  return sum * (pi / 2) / n * 2 * pi;
}

TEST(BsdfModel, GgxDistributionIntegratesWithCosineToOne) {
  for (double alpha : {0.01, 0.1, 0.5, 1.0})
    EXPECT_NEAR(model_d_cos_integral(alpha), 1.0, 1e-4) << alpha;
}

TEST(BsdfModel, SmithMaskingKnownValues) {
  EXPECT_DOUBLE_EQ(ggx_g1(real3(0, 0, 1), 0.5), 1.0);
  // tan theta = 1, alpha = 1: Lambda = (sqrt(2) - 1) / 2, G1 = 2 / (1 + sqrt(2)).
  const real3 w45 = model_dir(std::sqrt(0.5), 0.3);
  EXPECT_NEAR(ggx_g1(w45, 1.0), 2.0 / (1.0 + std::sqrt(2.0)), 1e-12);
  // tan theta = 2, alpha = 0.5: alpha tan = 1, the same Lambda.
  const real3 w = model_dir(1.0 / std::sqrt(5.0), 1.0);
  EXPECT_NEAR(ggx_lambda(w, 0.5), (std::sqrt(2.0) - 1.0) / 2.0, 1e-12);
  // Height-correlated G2 with one direction at the normal is G1 of the other.
  EXPECT_NEAR(ggx_g2(real3(0, 0, 1), w45, 1.0), ggx_g1(w45, 1.0), 1e-12);
}

// The visible normals' density integrates to 1 over the hemisphere of h (that is G1's
// definition), and its samples' mean of any function matches the density's integral of it.
TEST(BsdfModel, VisibleNormalDensityIntegratesToOneAndMatchesItsSamples) {
  for (double alpha : {0.1, 0.4, 1.0}) {
    const real3 wo = model_dir(0.4, 0.7);
    const int n = 1500;
    double total = 0.0, mean_hz = 0.0;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < 2 * n; ++b) {
        const double theta = (a + 0.5) / n * (pi / 2);
        const real3 h = model_dir(std::cos(theta), (b + 0.5) / (2 * n) * 2 * pi);
        const double p = ggx_pdf_vndf(wo, h, alpha) * std::sin(theta) * (pi / 2 / n) * (pi / n);
        total += p;
        mean_hz += p * h.z;
      }
    EXPECT_NEAR(total, 1.0, 2e-3) << alpha;
    double sampled = 0.0;
    const int m = 400;
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        sampled += ggx_sample_vndf(wo, alpha, real2((a + 0.5) / m, (b + 0.5) / m)).z;
    EXPECT_NEAR(sampled / (m * m), mean_hz, 2e-3) << alpha;
  }
}

// E(mu, r) integrated afresh with the kernel's own GGX: visible normals on a grid, crowded near
// u2 = 1 (GGX's tail), weight G2 / G1 where the reflection is above the surface.
double model_fresh_albedo(double mu, double r) {
  const double alpha = std::max(r * r, 1e-3);
  const real3 wo = model_dir(std::max(mu, 1e-4), 0.0);
  const int n = 256;
  double sum = 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double t = (b + 0.5) / n;
      const double u2 = 1.0 - std::pow(1.0 - t, 4.0);
      const real3 h = ggx_sample_vndf(wo, alpha, real2((a + 0.5) / n, u2));
      const real3 wi = reflect_about(wo, h);
      if (wi.z <= 0) continue;
      sum += ggx_g2(wo, wi, alpha) / ggx_g1(wo, alpha) * 4.0 * std::pow(1.0 - t, 3.0);
    }
  return sum / (n * n);
}

TEST(BsdfModel, CompensationTableEntriesMatchAFreshIntegration) {
  const int n = bsdf_table_size;
  for (int row : {4, 12, 20, 31})
    for (int col : {1, 8, 16, 31}) {
      const double x = double(col) / (n - 1);  // the columns are at cosine x^2
      const double fresh = model_fresh_albedo(x * x, double(row) / (n - 1));
      EXPECT_NEAR(bsdf_table_data[bsdf_ggx_e + row * n + col], fresh, 1e-4) << row << " " << col;
    }
}

// Roughness 0 metal is the book's mirror: one delta direction, the mirror one, weighing
// Schlick's Fresnel with F0 the base color (exactly the base color at normal incidence, and
// exactly 1 at any angle for a white metal).
TEST(BsdfModel, SmoothMetalIsTheMirror) {
  const real3 wo = model_dir(0.6, 0.4);
  for (real3 base : {real3(1.0), real3(0.9, 0.5, 0.2)}) {
    const pbr_surface m = pbr_surface_of(base, 1.0, 0.0);
    real3 wi, weight;
    double pdf = 0;
    bool delta = false;
    ASSERT_TRUE(pbr_sample(m, wo, real3(0.3, 0.6, 0.9), wi, weight, pdf, delta));
    EXPECT_TRUE(delta);
    EXPECT_EQ(wi, real3(-wo.x, -wo.y, wo.z));
    const real3 want = base + (real3(1.0) - base) * std::pow(1.0 - wo.z, 5.0);
    EXPECT_NEAR(weight.x, want.x, 1e-12);
    EXPECT_NEAR(weight.y, want.y, 1e-12);
    EXPECT_NEAR(weight.z, want.z, 1e-12);
    EXPECT_EQ(pbr_eval(m, wo, wi), real3(0.0));  // the delta lobe is not in the evaluation
    EXPECT_EQ(pbr_pdf(m, wo, wi), 0.0);
  }
  real3 wi, weight;
  double pdf = 0;
  bool delta = false;
  pbr_sample(pbr_surface_of(real3(1.0), 1.0, 0.0), wo, real3(0.5), wi, weight, pdf, delta);
  EXPECT_EQ(weight, real3(1.0));
}

// Transmission 1 at ior 1, roughness 0, no specular: the light goes straight through, exactly,
// with the base color; thin or not. And a rough refracting wall at ior 1 too: equal indices
// bend nothing however rough the interface (Walter's half vector is undefined there).
TEST(BsdfModel, ClearGlassOfIorOnePassesStraightThrough) {
  for (int variant = 0; variant < 3; ++variant) {
    const bool thin = variant == 1;
    pbr_surface m = pbr_surface_of(real3(0.8, 0.6, 0.3), 0.0, variant == 2 ? 0.5 : 0.0);
    m.transmission = 1.0;
    m.eta = 1.0;
    m.specular = 0.0;
    m.thin = thin;
    for (double c : {0.05, 0.5, 1.0}) {
      const real3 wo = model_dir(c, 2.0);
      real3 wi, weight;
      double pdf = 0;
      bool delta = false;
      ASSERT_TRUE(pbr_sample(m, wo, real3(0.7, 0.2, 0.4), wi, weight, pdf, delta));
      EXPECT_TRUE(delta);
      EXPECT_EQ(wi, -wo) << variant << " " << c;
      EXPECT_EQ(weight, m.base_color) << variant << " " << c;
      EXPECT_EQ(pbr_eval(m, wo, -wo), real3(0.0));  // no NaN from a vanishing half vector
    }
  }
}

// The mean weight of many samples: the integral of f |cos| over the sphere (the delta lobes'
// included), for one wo.
real3 model_albedo(const pbr_surface& m, real3 wo, int n = 128) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  real3 sum(0.0);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      real3 wi, weight;
      double pdf = 0;
      bool delta = false;
      const real3 u(uni(rng), (a + uni(rng)) / n, (b + uni(rng)) / n);
      if (pbr_sample(m, wo, u, wi, weight, pdf, delta)) sum += weight;
    }
  return sum / double(n * n);
}

TEST(BsdfModel, WhiteFurnaceOfRoughMetalAndDielectricIsOne) {
  for (double r : {0.0, 0.2, 0.5, 0.8, 1.0})
    for (double c : {0.1, 0.5, 0.95})
      for (double metallic : {1.0, 0.0}) {
        const real3 a = model_albedo(pbr_surface_of(real3(1.0), metallic, r), model_dir(c, 0.5));
        EXPECT_NEAR(a.x, 1.0, 0.01) << "roughness " << r << " cos " << c << " metal " << metallic;
      }
}

TEST(BsdfModel, EnergyNeverExceedsOne) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 60; ++k) {
    pbr_surface m = pbr_surface_of(real3(1.0), uni(rng), uni(rng));
    m.eta = k % 3 == 0 ? 1.0 / (1.0 + uni(rng)) : 1.0 + uni(rng);
    m.specular = uni(rng);
    m.specular_color = real3(uni(rng), 1.0, 2.0 * uni(rng));
    m.transmission = uni(rng);
    m.thin = k % 2 == 0;
    m.clearcoat = uni(rng);
    m.clearcoat_roughness = uni(rng);
    m.clearcoat_normal = unit_vector(real3(0.4 * uni(rng) - 0.2, 0.4 * uni(rng) - 0.2, 1.0));
    m.sheen_color = real3(uni(rng), 1.0, uni(rng));
    m.sheen_roughness = uni(rng);
    const real3 a = model_albedo(m, model_dir(0.02 + 0.98 * uni(rng), 1.0), 64);
    worst = std::max(worst, std::max(a.x, std::max(a.y, a.z)));
  }
  EXPECT_LE(worst, 1.01);
}

}  // namespace
}  // namespace rtvk
