// HDR environment maps (issue 46): reading them, the equirectangular convention, the importance
// sampler's density (environment.h) and what escaping rays see on the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "bsdf/chi_square.h"
#include "environment_scenes.h"
#include "errors.h"
#include "light_sources.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

using test::furnace_scene;
using test::sky_sun_map;
using test::uniform_map;
constexpr double test_pi = 3.14159265358979323846;

// The documented direction of (u, t) in the map's frame (docs/lighting.md).
vec3 direction_of(double u, double t) {
  const double phi = (2 * u - 1) * test_pi, theta = t * test_pi;
  return vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const usage_error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(EnvironmentFile, TheTestMapReadsAsWrittenAndItsRgbeIsExact) {
  const environment_map e = sky_sun_map();
  ASSERT_EQ(e.image->width, 256);
  ASSERT_EQ(e.image->height, 128);
  // RGBE words decode to what stb_image decoded, and encode back to the same words.
  for (float v : {0.0f, 1.0f, 0.25f, 5000.0f, 0x1p-100f, 1.0e38f}) {
    const std::uint32_t w = encode_rgbe(v, v / 2, 0);
    const double s = std::ldexp(1.0, int(w >> 24) - 136);
    EXPECT_NEAR((w & 255) * s, v, v / 128) << v;
    EXPECT_EQ(encode_rgbe(float((w & 255) * s), float(((w >> 8) & 255) * s), 0), w) << v;
  }
  // The sun's texels are its 4500-5000 radiance, the sky's below 1.1.
  const environment_tables t(e);
  const color sun = environment_radiance(t.view(), vec3(0.4096, 0.5736, 0.7094));
  EXPECT_GT(sun.x, 4000);
  EXPECT_LT(environment_radiance(t.view(), vec3(0, 1, 0)).z, 1.1);
}

TEST(EnvironmentFile, BadFilesAreRefusedNamingTheFieldAndTheFile) {
  test::temp_dir dir;
  const std::string missing = (dir.path() / "none.hdr").string();
  EXPECT_NE(
      refusal([&] { load_environment_image(missing, "--environment"); }).find("--environment"),
      std::string::npos);
  std::ifstream in(test::sky_sun_file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const std::string truncated = (dir.path() / "cut.hdr").string();
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 1000);
  const std::string cut = refusal([&] { load_environment_image(truncated, "/environment/file"); });
  EXPECT_NE(cut.find("/environment/file"), std::string::npos) << cut;
  EXPECT_NE(cut.find("truncated"), std::string::npos) << cut;
  const std::string text = (dir.path() / "text.hdr").string();
  std::ofstream(text) << "not an image";
  EXPECT_NE(refusal([&] { load_environment_image(text, "f"); }).find("not a Radiance"),
            std::string::npos);
  std::vector<float> rgb(12, 1.0f);
  rgb[4] = std::nanf("");
  EXPECT_NE(refusal([&] { environment_from_rgb(2, 2, rgb, "f"); }).find("texel 1,0"),
            std::string::npos);
  rgb[4] = -1;
  EXPECT_NE(refusal([&] { environment_from_rgb(2, 2, rgb, "f"); }).find("texel 1,0"),
            std::string::npos);
  // 8192x4096: its texels fit 128 MiB exactly, its sampling table does not.
  EXPECT_NE(refusal([&] { environment_from_rgb(8192, 4096, {}, "f"); }).find("past the limit"),
            std::string::npos);
}

// Blender's convention with y up: u = 1/2 looks along +x, u = 3/4 along +z, u = 0 along -x, the
// top row up; a texel at (u, t) is seen along direction_of(u, t), and rotation 90 turns it about
// +y, taking +x to -z.
TEST(EnvironmentConvention, ABrightTexelIsSeenAlongTheDocumentedDirection) {
  const int w = 64, h = 32;
  struct spot {
    int x, y;
    vec3 along;  // where the texel's center must be seen
  };
  for (const spot& s :
       {spot{32, 16, vec3(1, 0, 0)}, spot{48, 16, vec3(0, 0, 1)}, spot{16, 16, vec3(0, 0, -1)},
        spot{0, 16, vec3(-1, 0, 0)}, spot{40, 5, direction_of(40.5 / w, 5.5 / h)}}) {
    const environment_map e = uniform_map(w, h, 0.5f, s.x, s.y, 100.0f);
    const environment_tables t(e);
    const vec3 d = direction_of((s.x + 0.5) / w, (s.y + 0.5) / h);
    EXPECT_NEAR(glm::length(d - s.along), 0, 0.08) << s.x << "," << s.y;
    EXPECT_EQ(environment_radiance(t.view(), d).x, 100.0) << s.x << "," << s.y;
    EXPECT_EQ(environment_radiance(t.view(), -d).x, 0.5) << s.x << "," << s.y;
    environment_map turned = e;
    turned.rotation = 90;
    const environment_tables r(turned);
    // Turned 90 degrees about +y: (x, y, z) -> (z, y, -x).
    const vec3 turned_d(d.z, d.y, -d.x);
    EXPECT_EQ(environment_radiance(r.view(), turned_d).x, 100.0) << s.x << "," << s.y;
    EXPECT_EQ(environment_radiance(r.view(), d).x, 0.5) << s.x << "," << s.y;
  }
  // The top row looks up.
  const environment_tables top(uniform_map(w, h, 0.5f, 7, 0, 9.0f));
  EXPECT_EQ(environment_radiance(top.view(), direction_of(7.5 / w, 0.2 / h)).x, 9.0);
}

// The density integrates to 1 over the sphere: exactly, as pdf sin(theta) is constant in each
// texel, so a midpoint rule on a grid finer than the texels sums each texel's probability.
TEST(EnvironmentSampling, TheDensityIntegratesToOne) {
  for (double rotation : {0.0, 37.0}) {
    const environment_tables t(sky_sun_map(rotation));
    const int n_theta = 512, n_phi = 1024;
    double sum = 0;
    for (int i = 0; i < n_theta; ++i)
      for (int j = 0; j < n_phi; ++j) {
        const double theta = (i + 0.5) * test_pi / n_theta, phi = (j + 0.5) * 2 * test_pi / n_phi;
        const vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
        sum += environment_pdf(t.view(), d) * std::sin(theta);
      }
    EXPECT_NEAR(sum * (test_pi / n_theta) * (2 * test_pi / n_phi), 1.0, 2e-3) << rotation;
  }
}

// Each sample's density is environment_pdf's of its direction and its radiance
// environment_radiance's; the sun, 0.08% of the sphere, draws most samples.
TEST(EnvironmentSampling, ASamplesPdfAndRadianceAreThoseOfItsDirection) {
  const environment_tables t(sky_sun_map(25));
  std::mt19937_64 rng(46);
  std::uniform_real_distribution<double> uniform(0, 1);
  int sun = 0, pdf_off = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const light_sample s = environment_sample(t.view(), real2(uniform(rng), uniform(rng)));
    ASSERT_NEAR(glm::length(s.wi), 1, 1e-6);  // the rotation is float cos and sin
    ASSERT_EQ(s.distance, light_at_infinity);
    ASSERT_FALSE(s.delta);
    ASSERT_GT(s.pdf, 0);
    // The same texel, sin(theta) within the rotation's float rounding; a sample on a texel's
    // edge may land in its neighbor when turned back: rare.
    pdf_off += std::abs(environment_pdf(t.view(), s.wi) / s.pdf - 1) > 1e-6;
    if (environment_radiance(t.view(), s.wi) == s.radiance) sun += s.radiance.x > 1000;
  }
  EXPECT_LE(pdf_off, n / 1000);
  EXPECT_GT(sun, n / 2);
}

// Each bin's share of the density on `grid` (tests/bsdf's bins: cos theta about z, phi from x
// toward y), by the midpoint rule on cells 32 x 32 to a bin: the density is a staircase over the
// texels, which adaptive quadrature (integrate_bins) resolves slowly; cells this fine are within
// 1e-3 of the exact share, far inside the statistic's noise.
std::vector<double> bin_shares(const bsdf_test::sphere_grid& grid, const environment_tables& t) {
  std::vector<double> share(std::size_t(grid.bins()), 0);
  const int nz = grid.theta_res * 32, nphi = grid.phi_res * 32;
  const double dz = 2.0 / nz, dphi = 2 * test_pi / nphi;
  for (int i = 0; i < nz; ++i)
    for (int j = 0; j < nphi; ++j) {
      const double z = -1 + (i + 0.5) * dz, phi = (j + 0.5) * dphi;
      const double r = std::sqrt(1 - z * z);
      const glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
      share[std::size_t(grid.bin_of(w))] += environment_pdf(t.view(), w) * dz * dphi;
    }
  return share;
}

// Pearson's chi-square test of sampled directions against environment_pdf (tests/bsdf's
// harness), for a map of one bright texel and the test map turned.
TEST(EnvironmentSampling, SampledDirectionsFollowTheDensity) {
  for (double rotation : {0.0, 123.0}) {
    const environment_tables t(rotation == 0 ? uniform_map(32, 16, 1.0f, 20, 4, 30.0f)
                                             : sky_sun_map(rotation));
    const bsdf_test::sphere_grid grid{16, 32};
    const std::vector<double> share = bin_shares(grid, t);
    const int n = 200000;
    std::vector<double> observed(share.size(), 0), expected(share.size());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int i = 0; i < n; ++i)
      observed[std::size_t(
          grid.bin_of(environment_sample(t.view(), real2(uniform(rng), uniform(rng))).wi))] += 1;
    double total = 0;
    for (double v : share) total += v;
    for (std::size_t b = 0; b < share.size(); ++b) expected[b] = share[b] / total * n;
    const bsdf_test::chi_square_result r = bsdf_test::chi_square_test(observed, expected, 1e-3);
    EXPECT_TRUE(r.passed) << rotation << ": " << r.message;
  }
}

TEST(EnvironmentRender, AWhiteSphereInAUniformEnvironmentIsItsRadianceCpu) {
  const scene s = furnace_scene(0.75f);
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      ASSERT_NEAR(fb.at(x, y).g, 0.75, 1e-12) << "pixel " << x << "," << y;
}

// Not visible: camera rays that escape see the sky; the sphere is still lit by the map.
TEST(EnvironmentRender, AnInvisibleMapShowsTheSkyToCameraRaysOnly) {
  scene s = furnace_scene(0.75f);
  s.environment->visible = false;
  s.sky = {color(0.1), color(0.1)};
  const framebuffer fb = render_cpu(test::scene_camera(s), s, s.render);
  EXPECT_EQ(fb.at(0, 0).g, 0.1);              // a corner: the sky
  EXPECT_NEAR(fb.at(12, 12).g, 0.75, 1e-12);  // the sphere: the map
}

}  // namespace
}  // namespace rtvk
