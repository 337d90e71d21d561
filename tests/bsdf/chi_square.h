#pragma once
// Pearson's chi-square goodness-of-fit test of sampled directions against a density on the unit
// sphere, as Mitsuba 3 (python/mitsuba/chi2.py) and pbrt (bsdfs_test.cpp) test their BSDFs: the
// sphere is cut into bins of equal solid angle (equal steps of cos theta and of phi, where
// d omega = d cos(theta) d phi), each bin's expected count is the sample count times the density's
// integral over it (adaptive Simpson's rule, refined toward the peaks the caller names), bins
// expecting fewer than five samples are pooled, and the statistic's p-value is the upper
// regularized incomplete gamma function Q(dof / 2, statistic / 2).
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace rtvk::bsdf_test {

// The bins: theta_res steps of cos theta in [-1, 1] (both hemispheres) by phi_res steps of phi
// in [0, 2 pi).
struct sphere_grid {
  int theta_res = 10;  // bins in cos theta
  int phi_res = 20;    // bins in phi
  int bins() const { return theta_res * phi_res; }
  int bin_of(glm::dvec3 w) const;  // w: a direction (normalized here)
};

// A density over directions, per steradian.
using density = std::function<double(glm::dvec3)>;

// The integral of f over each bin of the grid (bin_of's order). f may be sharply peaked: peaks
// lists directions where it may be (a mirror direction, a refracted one), which every bin's
// integration takes as break points in cos theta and in phi, so that no narrow peak falls
// between the rule's nodes unseen. Each bin is integrated to an absolute error of about
// tolerance.
std::vector<double> integrate_bins(const sphere_grid& grid, const density& f,
                                   std::span<const glm::dvec3> peaks, double tolerance = 1e-7);

// The upper regularized incomplete gamma function Q(a, x) = Gamma(a, x) / Gamma(a): the
// probability that a chi-square variable of 2a degrees of freedom exceeds 2x.
double gamma_q(double a, double x);

// The per-test significance that keeps the chance of any false rejection among `tests`
// independent tests at alpha (Sidak's correction): 1 - (1 - alpha)^(1 / tests).
double sidak_significance(double alpha, int tests);

struct chi_square_result {
  double statistic = 0;  // Pearson's sum of (observed - expected)^2 / expected over the cells
  int dof = 0;           // cells after pooling, less one
  double p_value = 1;    // the chance of a statistic this large if the samples follow the density
  bool passed = true;    // p_value >= significance, and no sample where none is expected
  std::string message;   // why it failed, or the numbers when it passed
};

// Pearson's test of observed counts against expected ones (the same cells, summing to the same
// total). Cells expecting fewer than min_expected are pooled, smallest first, until the pool
// expects at least that many; a cell that expects (almost) nothing but saw a sample rejects at
// once, as Mitsuba's does.
chi_square_result chi_square_test(std::span<const double> observed,
                                  std::span<const double> expected, double significance,
                                  double min_expected = 5);

// The observed and expected counts as two tables of text, theta rows by phi columns (and the
// cells past the grid's bins, e.g. the samples that found no direction, as a last line), for a
// failure's message.
std::string histograms_text(const sphere_grid& grid, std::span<const double> observed,
                            std::span<const double> expected);

}  // namespace rtvk::bsdf_test
