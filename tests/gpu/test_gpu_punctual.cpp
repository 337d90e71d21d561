// punctual.h on the device (tests/gpu/probes/punctual_probe.comp): the GPU's punctual_sample,
// punctual_count, sun_radiance and sun_pdf are the float compilation's within stated bounds, on
// lights packed as gpu_scene packs them (to_gpu_punctuals); and the packing's count, unused
// element and specialization constant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "gpu/kernels_f32.h"
#include "gpu_fixture.h"
#include "gpu_scene.h"
#include "packing.h"
#include "probe.h"

namespace rtvk {
namespace {

class GpuPunctual : public test::GpuTest {};

scene lit_scene() {
  scene s;
  s.spheres.push_back(sphere(point3(0, 0, -1), 0.5, 0));
  s.materials.push_back({"gray", {material_type::lambertian, color(0.5), 0, 1.5}});
  punctual_light point;
  point.position = {1, 4, -2};
  point.tint = {1, 0.5, 0.25};
  point.intensity = 30;
  punctual_light spot = point;
  spot.kind = punctual_kind::spot;
  spot.direction = {0, -1, 0.2};
  spot.inner_cone = 15;
  spot.outer_cone = 50;
  punctual_light delta;
  delta.kind = punctual_kind::directional;
  delta.direction = {0.3, -1, 0.1};
  delta.intensity = 2;
  punctual_light big_sun = delta;
  big_sun.angular_diameter = 12;
  punctual_light small_sun = delta;
  small_sun.direction = {-0.5, -1, -0.4};
  small_sun.angular_diameter = 0.53;
  small_sun.intensity = 100000;
  s.punctual_lights = {point, spot, delta, big_sun, small_sun};
  return s;
}

double rel(double a, double b) {
  return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-6});
}

// Five lights (point, spot, delta directional, a 12-degree sun, a 0.53-degree one), 40 random
// points and numbers each, query directions inside each sun's disk (a sample's own direction)
// and outside: the device and the float compilation agree exactly on the count, delta and
// whether a direction is in a disk (no query near an edge), on directions to 1e-5 and on
// radiance, distance and densities to 1e-5 relative (the device's sqrt and division are within
// 3 ulp of exact; a sun's azimuth is turn_cos_sin's polynomial, exactly rounded operations).
// Measured: 0 on lavapipe (Mesa 22.3 and Mesa 25), bit for bit.
TEST_F(GpuPunctual, TheDeviceSamplesAsTheFloatCompilation) {
  const std::vector<gpu::gpu_punctual> lights = gpu::to_gpu_punctuals(lit_scene());
  ASSERT_EQ(lights.size(), 5u);
  std::mt19937_64 rng(0x46);
  std::uniform_real_distribution<float> u01(0.0f, 0.999f), box(-3.0f, 3.0f);
  std::vector<gpu::punctual_probe_entry> in;
  for (std::uint32_t k = 0; k < lights.size(); ++k)
    for (int i = 0; i < 40; ++i) {
      gpu::punctual_probe_entry e{};
      e.light = k;
      e.p = glm::vec3(box(rng), box(rng), box(rng));
      e.u = glm::vec2(u01(rng), u01(rng));
      // Half the queries toward the light's own sample (inside a sun's disk), half away from it.
      gpu::punctual_probe_entry cpu = e;
      f32::run_punctual_probe(lights, cpu);
      e.query = i % 2 ? cpu.wi : -cpu.wi;
      in.push_back(e);
    }
  const std::vector<gpu::punctual_probe_entry> out = gpu::run_punctual_probe(gpu(), lights, in);
  int suns_seen = 0;
  double worst = 0;  // the largest relative gap, printed for the record
  for (std::size_t i = 0; i < in.size(); ++i) {
    gpu::punctual_probe_entry want = in[i];
    f32::run_punctual_probe(lights, want);
    const gpu::punctual_probe_entry& got = out[i];
    SCOPED_TRACE("light " + std::to_string(in[i].light) + " entry " + std::to_string(i));
    EXPECT_EQ(got.count, 5u);
    EXPECT_EQ(got.delta, want.delta);
    EXPECT_LT(glm::length(got.wi - want.wi), 1e-5f);
    std::vector<double> gaps = {rel(got.distance, want.distance), rel(got.pdf, want.pdf),
                                rel(got.sun_pdf, want.sun_pdf)};
    for (int c = 0; c < 3; ++c) {
      gaps.push_back(rel(got.radiance[c], want.radiance[c]));
      gaps.push_back(rel(got.sun_radiance[c], want.sun_radiance[c]));
    }
    for (const double g : gaps) EXPECT_LT(g, 1e-5);
    worst = std::max({worst, *std::max_element(gaps.begin(), gaps.end()),
                      double(glm::length(got.wi - want.wi))});
    if (want.sun_pdf > 0) ++suns_seen;
  }
  EXPECT_EQ(suns_seen, 40);
  std::cout << "punctual probe: largest gap to the float compilation " << worst
            << "\n";  // both suns' 20 queries inside their disks: the probe saw them
}

// What gpu_scene binds: the scene's lights each with their count, and one unused element with
// count 0 (RTVK_SPEC_PUNCTUAL false) when it has none.
TEST_F(GpuPunctual, ThePackingCountsTheLightsAndSpecializesOnThem) {
  scene s = lit_scene();
  const std::vector<gpu::gpu_punctual> lights = gpu::to_gpu_punctuals(s);
  for (const gpu::gpu_punctual& g : lights) EXPECT_EQ(g.count, 5u);
  EXPECT_EQ(lights[1].kind, RTVK_PUNCTUAL_SPOT);
  EXPECT_NEAR(glm::length(lights[1].direction), 1.0f, 1e-6f);
  EXPECT_FLOAT_EQ(lights[0].intensity.y, 15.0f);
  EXPECT_EQ(lights[2].cone_gap, 0.0f);
  EXPECT_NEAR(lights[3].cone_gap, 1 - std::cos(6 * 3.14159265358979 / 180), 1e-7);
  std::uint32_t spec[RTVK_SPEC_COUNT] = {};
  gpu::gpu_scene(gpu(), s, true).specialize(spec);
  EXPECT_EQ(spec[RTVK_SPEC_PUNCTUAL], 1u);

  s.punctual_lights.clear();
  const std::vector<gpu::gpu_punctual> none = gpu::to_gpu_punctuals(s);
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].count, 0u);
  std::uint32_t spec_none[RTVK_SPEC_COUNT] = {};
  gpu::gpu_scene(gpu(), s, true).specialize(spec_none);
  EXPECT_EQ(spec_none[RTVK_SPEC_PUNCTUAL], 0u);
  // The probe reads count 0 from the unused element.
  gpu::punctual_probe_entry e{};
  e.query = glm::vec3(0, 1, 0);
  e.p = glm::vec3(0, 0, 0);
  EXPECT_EQ(gpu::run_punctual_probe(gpu(), none, {e})[0].count, 0u);
}

}  // namespace
}  // namespace rtvk
