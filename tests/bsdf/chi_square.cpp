#include "chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include <glm/geometric.hpp>

namespace rtvk::bsdf_test {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

// A unit direction from its cos theta and phi.
glm::dvec3 direction_of(double z, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

double phi_of(glm::dvec3 w) {
  const double phi = std::atan2(w.y, w.x);
  return phi < 0 ? phi + two_pi : phi;
}

// Adaptive Simpson's rule on [a, b] (Lyness): halves a panel until its two halves agree with the
// whole to 15 eps, or to a millionth of it, or the depth or the evaluations run out. Those two
// limits are what ends it where the integrand is not smooth on the scale of doubles: the float
// compilation's density at a direction rounded to float is a staircase (steps of 6e-8 in cos
// theta, a few percent of GGX's density at roughness 0.05 near its peak), and a step never
// satisfies a tolerance that halves with the panel. The budget is shared by the whole interval,
// so that such a staircase costs a bounded number of evaluations, not a full binary tree.
template <typename F>
double adapt(const F& f, double a, double b, double fa, double fm, double fb, double whole,
             double eps, int depth, int& budget) {
  const double m = 0.5 * (a + b);
  const double flm = f(0.5 * (a + m)), frm = f(0.5 * (m + b));
  budget -= 2;
  const double left = (m - a) / 6 * (fa + 4 * flm + fm);
  const double right = (b - m) / 6 * (fm + 4 * frm + fb);
  const double delta = left + right - whole;
  // A NaN or an infinity stops here too (and reaches the sum, which the tests then reject).
  if (depth <= 0 || budget <= 0 || !std::isfinite(delta) ||
      std::abs(delta) <= std::max(15 * eps, 1e-6 * std::abs(left + right)))
    return left + right + delta / 15;
  return adapt(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1, budget) +
         adapt(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1, budget);
}

// The integral of f over [a, b] to about eps, in at most `budget` evaluations of f (past it, the
// panels not yet settled keep the estimate they have): four panels to start, and a break at
// every point of `breaks` inside the interval, each panel refined on its own.
template <typename F>
double integrate_1d(const F& f, double a, double b, std::span<const double> breaks, double eps,
                    int budget) {
  std::vector<double> cuts;
  for (int k = 0; k <= 4; ++k) cuts.push_back(a + (b - a) * k / 4);
  for (double x : breaks)
    if (x > a && x < b) cuts.push_back(x);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double x0 = cuts[k], x1 = cuts[k + 1];
    if (x1 <= x0) continue;
    const double f0 = f(x0), f1 = f(x1), fm = f(0.5 * (x0 + x1));
    const double whole = (x1 - x0) / 6 * (f0 + 4 * fm + f1);
    sum += adapt(f, x0, x1, f0, fm, f1, whole, eps * (x1 - x0) / (b - a), 50, budget);
  }
  return sum;
}

}  // namespace

int sphere_grid::bin_of(glm::dvec3 w) const {
  w = glm::normalize(w);
  const double z = std::clamp(w.z, -1.0, 1.0);
  const int t = std::clamp(int((z + 1) / 2 * theta_res), 0, theta_res - 1);
  const int p = std::clamp(int(phi_of(w) / two_pi * phi_res), 0, phi_res - 1);
  return t * phi_res + p;
}

std::vector<double> integrate_bins(const sphere_grid& grid, const density& f,
                                   std::span<const glm::dvec3> peaks, double tolerance) {
  std::vector<double> z_breaks, phi_breaks;
  for (glm::dvec3 p : peaks) {
    p = glm::normalize(p);
    z_breaks.push_back(p.z);
    phi_breaks.push_back(phi_of(p));
  }
  std::vector<double> out(grid.bins());
  for (int t = 0; t < grid.theta_res; ++t) {
    const double z0 = -1 + 2.0 * t / grid.theta_res, z1 = -1 + 2.0 * (t + 1) / grid.theta_res;
    for (int p = 0; p < grid.phi_res; ++p) {
      const double phi0 = two_pi * p / grid.phi_res, phi1 = two_pi * (p + 1) / grid.phi_res;
      // d omega = d cos(theta) d phi: the inner integral runs over phi at one cos theta.
      const auto over_phi = [&](double z) {
        const auto g = [&](double phi) { return f(direction_of(z, phi)); };
        return integrate_1d(g, phi0, phi1, phi_breaks, tolerance / (z1 - z0), 4000);
      };
      out[t * grid.phi_res + p] = integrate_1d(over_phi, z0, z1, z_breaks, tolerance, 1000);
    }
  }
  return out;
}

double gamma_q(double a, double x) {
  if (x <= 0) return 1;
  const double log_prefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {  // the series of P(a, x), Q = 1 - P
    double term = 1 / a, sum = term;
    for (int n = 1; n < 1000 && std::abs(term) > std::abs(sum) * 1e-16; ++n) {
      term *= x / (a + n);
      sum += term;
    }
    return std::max(0.0, 1 - sum * std::exp(log_prefix));
  }
  // Q's continued fraction, by Lentz's method.
  const double tiny = 1e-300;
  double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1) < 1e-16) break;
  }
  return std::exp(log_prefix) * h;
}

double sidak_significance(double alpha, int tests) {
  return 1 - std::pow(1 - alpha, 1.0 / tests);
}

chi_square_result chi_square_test(std::span<const double> observed,
                                  std::span<const double> expected, double significance,
                                  double min_expected) {
  chi_square_result r;
  std::vector<std::size_t> order(expected.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
  double pool_observed = 0, pool_expected = 0;
  int cells = 0;
  for (std::size_t i : order) {
    if (observed[i] > 0 && expected[i] <= 1e-9) {
      r.passed = false;
      r.p_value = 0;
      r.message = std::to_string(int(observed[i])) + " samples in cell " + std::to_string(i) +
                  ", whose expected count is " + std::to_string(expected[i]);
      return r;
    }
    if (expected[i] < min_expected || pool_expected < min_expected) {
      pool_observed += observed[i];
      pool_expected += expected[i];
      continue;
    }
    const double d = observed[i] - expected[i];
    r.statistic += d * d / expected[i];
    ++cells;
  }
  if (pool_expected > 0) {
    const double d = pool_observed - pool_expected;
    r.statistic += d * d / pool_expected;
    ++cells;
  }
  r.dof = cells - 1;
  r.p_value = r.dof > 0 ? gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
  r.passed = r.p_value >= significance;
  char line[160];
  std::snprintf(line, sizeof line, "chi-square %.2f, %d degrees of freedom, p-value %.3g (%s %.3g)",
                r.statistic, r.dof, r.p_value, r.passed ? "accepted at" : "rejected below",
                significance);
  r.message = line;
  return r;
}

std::string histograms_text(const sphere_grid& grid, std::span<const double> observed,
                            std::span<const double> expected) {
  std::string s;
  char cell[32];
  for (const auto& [name, counts] : {std::pair{"observed", observed}, {"expected", expected}}) {
    s += std::string(name) + " (rows: cos theta from -1 up; columns: phi from 0)\n";
    for (int t = 0; t < grid.theta_res; ++t) {
      for (int p = 0; p < grid.phi_res; ++p) {
        std::snprintf(cell, sizeof cell, "%7.0f", counts[t * grid.phi_res + p]);
        s += cell;
      }
      s += '\n';
    }
    for (std::size_t k = grid.bins(); k < counts.size(); ++k) {
      std::snprintf(cell, sizeof cell, "%.1f ", counts[k]);
      s += std::string("past the grid: ") + cell + '\n';
    }
  }
  return s;
}

}  // namespace rtvk::bsdf_test
