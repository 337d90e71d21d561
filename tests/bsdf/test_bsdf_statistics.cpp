// pbr.h's BSDF proved the way Mitsuba 3 and pbrt-v4 prove theirs, through its interface alone
// (pbr_sample, pbr_pdf, pbr_eval), on both of its C++ compilations (double: the CPU reference's;
// float: the GPU's arithmetic on the host) at every point of statistics_points(): the sampled
// directions follow the density (Pearson's chi-square), the density integrates to the share of
// samples that are neither delta nor absorbed, and each sample's weight and pdf are what eval and
// pdf say of its direction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numeric>
#include <random>

#include <glm/geometric.hpp>

#include "bsdf_under_test.h"
#include "chi_square.h"

namespace rtvk::bsdf_test {
namespace {

constexpr int kSamples = 200000;  // per point: a 1% deviation in a 5%-bin is 3 sigma
constexpr double kAlpha = 0.01;   // the chance that any chi-square test of the suite rejects a
                                  // correct BSDF (Sidak's correction shares it among the tests)
const sphere_grid kGrid{10, 20};

// What the tests of one (compilation, point) share: the histogram of the sampled non-delta
// directions and the density's integral over each bin, one past the grid for the samples that
// found no non-delta direction (delta or absorbed).
struct point_run {
  std::vector<double> observed;  // kGrid.bins() + 1 counts
  std::vector<double> expected;  // the same cells: kSamples x the density's integral
  double pdf_integral = 0;       // the density over the whole sphere
  int non_delta = 0;             // samples with a non-delta direction
};

std::mt19937_64 rng_of(std::size_t point, int salt) {
  return std::mt19937_64(0x5eedb5dfULL * (point + 1) + std::uint64_t(salt));
}

// The double compilation's density over each bin of kGrid at a point, once for both
// compilations (the integrals are most of the suite's time); run_of holds the lock.
const std::vector<double>& bin_integrals(std::size_t index) {
  static std::map<std::size_t, std::vector<double>> tables;
  auto [it, fresh] = tables.try_emplace(index);
  if (!fresh) return it->second;
  const bsdf_point& p = statistics_points()[index];
  // The density is the double compilation's for both: the float one, at directions rounded to
  // float, is a staircase near a sharp lobe (cos theta steps by 6e-8 near the pole, where GGX at
  // roughness 0.05 is 3e-6 wide), which no quadrature integrates to 1e-4 (it came to 1.08 at
  // roughness 0.05, normal incidence). The float samples must follow the model's density; the
  // float density's agreement with its own samples is WeightIsEvalOverPdfForEachSample's.
  const auto model = bsdf_of(compilation::double_precision, p.material);
  const std::vector<glm::dvec3> peaks = peaks_of(p);
  it->second = integrate_bins(
      kGrid, [&](glm::dvec3 wi) { return model->pdf(p.wo, wi); }, peaks);
  return it->second;
}

const point_run& run_of(compilation c, std::size_t index) {
  static std::mutex lock;
  static std::map<std::pair<int, std::size_t>, point_run> runs;
  const std::lock_guard<std::mutex> hold(lock);
  auto [it, fresh] = runs.try_emplace({int(c), index});
  point_run& r = it->second;
  if (!fresh) return r;
  const bsdf_point& p = statistics_points()[index];
  const auto bsdf = bsdf_of(c, p.material);
  r.observed.assign(kGrid.bins() + 1, 0.0);
  auto rng = rng_of(index, 1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < kSamples; ++k) {
    const glm::dvec3 u(uniform(rng), uniform(rng), uniform(rng));
    const bsdf_sample s = bsdf->sample(p.wo, u);
    if (s.sampled && !s.delta) {
      ++r.observed[kGrid.bin_of(s.wi)];
      ++r.non_delta;
    } else {
      ++r.observed[kGrid.bins()];
    }
  }
  r.expected = bin_integrals(index);
  r.pdf_integral = std::accumulate(r.expected.begin(), r.expected.end(), 0.0);
  for (double& e : r.expected) e *= kSamples;
  r.expected.push_back(std::max(0.0, kSamples * (1 - r.pdf_integral)));
  return r;
}

using point_case = std::tuple<compilation, std::size_t>;

class BsdfStatistics : public testing::TestWithParam<point_case> {
 protected:
  compilation comp() const { return std::get<0>(GetParam()); }
  std::size_t index() const { return std::get<1>(GetParam()); }
  const bsdf_point& point() const { return statistics_points()[index()]; }
  std::string where() const { return std::string(name_of(comp())) + ", " + point().name; }
};

// Pearson's test of the sampled non-delta directions against pbr_pdf's integral over each bin,
// with one more cell for the samples that found none (delta or absorbed), which expects what the
// density leaves of 1. The significance is kAlpha shared among every point of both compilations.
TEST_P(BsdfStatistics, SampledDirectionsFollowTheDensity) {
  const point_run& r = run_of(comp(), index());
  const double significance = sidak_significance(kAlpha, 2 * int(statistics_points().size()));
  const chi_square_result result = chi_square_test(r.observed, r.expected, significance);
  EXPECT_TRUE(result.passed) << where() << ": " << result.message << "\n"
                             << histograms_text(kGrid, r.observed, r.expected);
}

// The density integrates over the sphere (both hemispheres) to the share of samples with a
// non-delta direction: 1 for a BSDF without delta lobes that never absorbs. (The double
// compilation's density, for the float compilation's samples too: see run_of.) Within 5 binomial
// standard deviations of the share and the integration's error (1e-4), and never above 1.
TEST_P(BsdfStatistics, TheDensityIntegratesToTheShareOfNonDeltaSamples) {
  const point_run& r = run_of(comp(), index());
  const double share = double(r.non_delta) / kSamples;
  const double sigma = std::sqrt(std::max(share * (1 - share), 1.0 / kSamples) / kSamples);
  EXPECT_NEAR(r.pdf_integral, share, 5 * sigma + 1e-4) << where();
  EXPECT_LE(r.pdf_integral, 1 + 1e-4) << where();
}

double relative_error(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-30});
}

// Every non-delta sample's pdf is pbr_pdf of its direction, and its weight is pbr_eval over that
// pdf, channel by channel: to 1e-6 relative in double, 1e-4 in float (the sample forms them by
// other operations than eval and pdf do, and float keeps 7 digits). A delta sample's weight is
// finite and not negative; every direction is a unit vector.
TEST_P(BsdfStatistics, WeightIsEvalOverPdfForEachSample) {
  const bsdf_point& p = point();
  const auto bsdf = bsdf_of(comp(), p.material);
  const double tolerance = comp() == compilation::double_precision ? 1e-6 : 1e-4;
  auto rng = rng_of(index(), 2);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int checked = 0, wrong = 0;
  std::string first;
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 u(uniform(rng), uniform(rng), uniform(rng));
    const bsdf_sample s = bsdf->sample(p.wo, u);
    if (!s.sampled) continue;
    bool bad = std::abs(glm::length(s.wi) - 1) > 10 * tolerance;
    for (int c = 0; c < 3; ++c) bad |= !(std::isfinite(s.weight[c]) && s.weight[c] >= 0);
    if (!s.delta) {
      ++checked;
      const double pdf = bsdf->pdf(p.wo, s.wi);
      const glm::dvec3 f = bsdf->eval(p.wo, s.wi);
      bad |= !(s.pdf > 0) || relative_error(s.pdf, pdf) > tolerance;
      for (int c = 0; c < 3; ++c) bad |= relative_error(s.weight[c], f[c] / pdf) > tolerance;
      if (bad && first.empty())
        first = "wi (" + std::to_string(s.wi.x) + ", " + std::to_string(s.wi.y) + ", " +
                std::to_string(s.wi.z) + "): sample's pdf " + std::to_string(s.pdf) + ", pbr_pdf " +
                std::to_string(pdf) + "; weight.r " + std::to_string(s.weight.r) +
                ", eval.r / pdf " + std::to_string(f.r / pdf);
    }
    wrong += bad;
  }
  EXPECT_EQ(wrong, 0) << where() << ": of " << checked << " non-delta samples; first: " << first;
}

std::vector<point_case> all_cases() {
  std::vector<point_case> v;
  for (compilation c : {compilation::double_precision, compilation::single_precision})
    for (std::size_t i = 0; i < statistics_points().size(); ++i) v.emplace_back(c, i);
  return v;
}

INSTANTIATE_TEST_SUITE_P(Points, BsdfStatistics, testing::ValuesIn(all_cases()),
                         [](const testing::TestParamInfo<point_case>& info) {
                           return std::string(name_of(std::get<0>(info.param))) + "_" +
                                  std::to_string(std::get<1>(info.param));
                         });

}  // namespace
}  // namespace rtvk::bsdf_test
