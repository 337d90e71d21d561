// The chi-square harness itself (chi_square.h): its p-values are the chi-square distribution's,
// its integrals find a peak far narrower than a bin, and it rejects samples drawn from another
// density than the one tested while it accepts those drawn from it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>

#include "chi_square.h"

namespace rtvk::bsdf_test {
namespace {

// Critical values from the chi-square tables (Abramowitz and Stegun 26.8), and for 199 degrees of
// freedom mpmath's gammainc(a, x, inf, regularized=True).
TEST(ChiSquareHarness, PValuesAreTheChiSquareDistributions) {
  EXPECT_NEAR(gamma_q(0.5, 3.841459 / 2), 0.05, 1e-6);            // 1 degree of freedom
  EXPECT_NEAR(gamma_q(5.0, 23.20925 / 2), 0.01, 1e-6);            // 10
  EXPECT_NEAR(gamma_q(99.5, 248.0 / 2), 0.0103856434138, 1e-11);  // 199: continued fraction
  EXPECT_NEAR(gamma_q(99.5, 160.0 / 2), 0.9805637490891, 1e-11);  // 199: the series
  EXPECT_NEAR(gamma_q(1.0, 2.0), std::exp(-2.0), 1e-14);          // 2 degrees: Q = exp(-x / 2)
  EXPECT_NEAR(sidak_significance(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(sidak_significance(0.01, 100), 1.005e-4, 1e-7);
}

// A von Mises-Fisher lobe of concentration 1e7 (0.02 degrees wide, ten times narrower than GGX
// at roughness 0.05) toward a direction inside a bin: its integrals over the bins sum to 1 when
// the harness is told where the peak is. (Untold, they come to 2e-11: the rule's nodes never
// see it.)
TEST(ChiSquareHarness, BinIntegralsFindANarrowPeakTheyAreToldOf) {
  const double kappa = 1e7;
  const glm::dvec3 mu = glm::normalize(glm::dvec3(0.3, 0.2, 0.5));
  const density vmf = [&](glm::dvec3 w) {
    return kappa / (2 * std::numbers::pi) * std::exp(kappa * (glm::dot(w, mu) - 1));
  };
  const sphere_grid grid;
  const glm::dvec3 peaks[] = {mu};
  const std::vector<double> bins = integrate_bins(grid, vmf, peaks);
  EXPECT_NEAR(std::accumulate(bins.begin(), bins.end(), 0.0), 1.0, 1e-5);
  EXPECT_NEAR(bins[grid.bin_of(mu)], 1.0, 1e-5);
}

// Cosine-distributed samples against the cosine density pass; the same samples against a
// density a tenth steeper, or against the uniform density of the hemisphere, fail.
TEST(ChiSquareHarness, AcceptsTheRightDensityAndRejectsWrongOnes) {
  const sphere_grid grid;
  const int n = 200000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> observed(grid.bins(), 0.0);
  for (int k = 0; k < n; ++k) {
    const double r = std::sqrt(uniform(rng)), phi = 2 * std::numbers::pi * uniform(rng);
    ++observed[grid.bin_of({r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - r * r)})];
  }
  const auto test = [&](const density& pdf) {
    std::vector<double> expected = integrate_bins(grid, pdf, {});
    for (double& e : expected) e *= n;
    return chi_square_test(observed, expected, 0.01);
  };
  const double pi = std::numbers::pi;
  EXPECT_TRUE(test([&](glm::dvec3 w) { return std::max(w.z, 0.0) / pi; }).passed);
  // cos^1.1 normalized: (1.1 + 1) cos^1.1 / (2 pi)
  EXPECT_FALSE(
      test([&](glm::dvec3 w) { return w.z > 0 ? 2.1 * std::pow(w.z, 1.1) / (2 * pi) : 0; }).passed);
  EXPECT_FALSE(test([&](glm::dvec3 w) { return w.z > 0 ? 1 / (2 * pi) : 0; }).passed);
  // A sample where the density is zero rejects at once.
  observed[0] += 1;
  const chi_square_result r = test([&](glm::dvec3 w) { return std::max(w.z, 0.0) / pi; });
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.p_value, 0.0) << r.message;
}

}  // namespace
}  // namespace rtvk::bsdf_test
