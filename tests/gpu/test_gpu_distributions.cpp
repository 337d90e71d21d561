// The scattering distributions the GPU draws, checked against the book's math computed here
// independently, in double: the metal's fuzz is a uniform point of a ball around the mirror
// direction, and glass reflects with Schlick's probability and refracts by Snell's law. The
// white furnace (test_furnace.cpp) cannot see these: a wrong direction still carries all the
// energy. Each case draws 20,000 samples from fixed streams through the kernel probe (the
// shader's own scatter), so the statistics are repeatable; the bounds are 4 standard errors (or
// a Kolmogorov-Smirnov distance at the 0.01 level), and each was seen to fail with the
// distribution it guards broken.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gpu_fixture.h"
#include "probe.h"

namespace rtvk {
namespace {

class GpuDistributions : public test::GpuTest {};

constexpr int samples = 20000;
constexpr double pi = 3.14159265358979323846;

glm::dvec3 mirror(glm::dvec3 d, glm::dvec3 n) {
  return d - 2 * glm::dot(d, n) * n;
}

// Entries for one material at one hit: the ray arrives along `direction` at the origin on a
// surface whose normal is +z; the streams differ by key.
std::vector<gpu::kernel_probe_entry> one_hit(std::uint32_t type, glm::vec3 direction, float fuzz,
                                             float ir, bool front_face) {
  std::vector<gpu::kernel_probe_entry> entries(samples);
  for (int i = 0; i < samples; ++i) {
    gpu::kernel_probe_entry& e = entries[std::size_t(i)];
    e.p = glm::vec3(0);
    e.offset = 0;
    e.normal = glm::vec3(0, 0, 1);
    e.front_face = front_face ? 1u : 0u;
    e.direction = direction;
    e.type = type;
    e.albedo = glm::vec3(0.5f);
    e.fuzz = fuzz;
    e.ir = ir;
    e.key = 0x9e3779b9u * std::uint32_t(i + 1);
    e.bounce = 1;
  }
  return entries;
}

// The largest distance between the empirical distribution of `u` and the uniform one on [0, 1].
double ks_distance_from_uniform(std::vector<double> u) {
  std::sort(u.begin(), u.end());
  double d = 0;
  const double n = double(u.size());
  for (std::size_t i = 0; i < u.size(); ++i)
    d = std::max({d, std::abs(double(i + 1) / n - u[i]), std::abs(u[i] - double(i) / n)});
  return d;
}

// Metal: the scattered direction is mirror + fuzz * p with p uniform in the unit ball, absorbed
// when it points into the surface. So (direction - mirror) / fuzz lies in the ball, |p|^3 is
// uniform on [0, 1] (the ball's volume grows as r^3), each component has mean 0 and mean square
// 1/5, and at 45 degrees with fuzz 1 the absorbed share is the ball's cap below z = -cos 45:
// (1 - h)^2 (2 + h) / 4 with h = 0.7071, 5.81%.
TEST_F(GpuDistributions, MetalFuzzIsUniformInABallAroundTheMirrorDirection) {
  const glm::dvec3 d = glm::normalize(glm::dvec3(1, 0, -1));
  const glm::dvec3 r = mirror(d, glm::dvec3(0, 0, 1));
  for (const float fuzz : {1.0f, 0.3f}) {
    SCOPED_TRACE("fuzz " + std::to_string(fuzz));
    const auto out =
        gpu::run_kernel_probe(gpu(), one_hit(RTVK_MATERIAL_METAL, glm::vec3(d), fuzz, 1.5f, true));
    std::vector<double> volume;
    glm::dvec3 mean(0), square(0);
    int absorbed = 0, outside = 0;
    for (const auto& e : out) {
      const glm::dvec3 p = (glm::dvec3(e.direction_out) - r) / double(fuzz);
      outside += glm::length(p) > 1 + 1e-5;
      volume.push_back(std::pow(std::min(glm::length(p), 1.0), 3));
      mean += p;
      square += p * p;
      absorbed += e.scattered == 0;
      // Scattered exactly when the direction leaves the surface.
      EXPECT_EQ(e.scattered != 0, e.direction_out.z > 0) << e.direction_out.z;
    }
    EXPECT_EQ(outside, 0);
    EXPECT_LE(ks_distance_from_uniform(volume), 1.63 / std::sqrt(double(samples)));
    mean /= double(samples);
    square /= double(samples);
    const double se_mean = std::sqrt(0.2 / samples);
    const double se_square = std::sqrt((3.0 / 35 - 0.04) / samples);  // E[x^4] = 3/35 in a ball
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(mean[k], 0, 4 * se_mean) << "axis " << k;
      EXPECT_NEAR(square[k], 0.2, 4 * se_square) << "axis " << k;
    }
    const double h = std::sqrt(0.5) / double(fuzz);  // the mirror's depth below the surface, in p
    const double want = h >= 1 ? 0 : (1 - h) * (1 - h) * (2 + h) / 4;
    EXPECT_NEAR(double(absorbed) / samples, want,
                4 * std::sqrt(std::max(want * (1 - want), 1e-4) / samples));
  }
}

// Schlick's reflectance, written here from the book, not taken from the kernels.
double schlick(double cosine, double ratio) {
  const double r0 = std::pow((1 - ratio) / (1 + ratio), 2);
  return r0 + (1 - r0) * std::pow(1 - cosine, 5);
}

// Glass of index 1.5, entered and left at several angles: each ray is reflected (the mirror
// direction) or refracted (Snell's law: the tangential part scaled by the index ratio, the
// normal part what keeps it a unit vector, into the surface); the reflected share is Schlick's
// reflectance, and 1 past the critical angle (41.8 degrees leaving the glass).
TEST_F(GpuDistributions, GlassReflectsWithSchlicksProbabilityAndRefractsBySnellsLaw) {
  struct incidence {
    double degrees;
    bool entering;
  };
  for (const incidence in :
       {incidence{0, true}, incidence{30, true}, incidence{60, true}, incidence{85, true},
        incidence{30, false}, incidence{41, false}, incidence{45, false}}) {
    SCOPED_TRACE(std::to_string(in.degrees) + (in.entering ? " degrees, entering" : ", leaving"));
    const double a = in.degrees * pi / 180;
    const glm::dvec3 d(std::sin(a), 0, -std::cos(a));
    const glm::dvec3 n(0, 0, 1);
    const double ratio = in.entering ? 1 / 1.5 : 1.5;
    const double sin_t = ratio * std::sin(a);
    const auto out = gpu::run_kernel_probe(
        gpu(), one_hit(RTVK_MATERIAL_DIELECTRIC, glm::vec3(d), 0, 1.5f, in.entering));
    const glm::dvec3 reflected = mirror(d, n);
    const glm::dvec3 refracted =
        sin_t <= 1 ? glm::dvec3(sin_t, 0, -std::sqrt(1 - sin_t * sin_t)) : glm::dvec3(0);
    int reflections = 0, neither = 0;
    for (const auto& e : out) {
      const glm::dvec3 got(e.direction_out);
      ASSERT_NE(e.scattered, 0u);
      if (glm::length(got - reflected) < 1e-5)
        ++reflections;
      else if (sin_t > 1 || glm::length(got - refracted) >= 1e-5)
        ++neither;
    }
    EXPECT_EQ(neither, 0) << "directions that are neither the mirror's nor Snell's";
    const double want = sin_t > 1 ? 1 : schlick(std::cos(a), ratio);
    EXPECT_NEAR(double(reflections) / samples, want,
                4 * std::sqrt(std::max(want * (1 - want), 1e-4) / samples))
        << reflections << " of " << samples << " reflected";
  }
}

}  // namespace
}  // namespace rtvk
