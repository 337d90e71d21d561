// The shared kernels (shaders/shared) called from C++ and from the probe shaders on the same
// inputs. The C++ side is the kernels' float compilation (kernels_f32.h): where a kernel uses only
// +, - and * (which Vulkan rounds correctly, as C++ does) the two must agree bit for bit; where it
// divides, takes a square root or a sine, the device may round differently, and the bound is
// stated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "camera.h"
#include "gpu_fixture.h"
#include "kernels_f32.h"
#include "packing.h"
#include "probe.h"
#include "random.h"
#include "sample_sum.h"
#include "scene.h"

namespace rtvk {
namespace {

class GpuKernels : public test::GpuTest {};

bool same_bits(float a, float b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// How many float steps apart a and b are (0: equal).
std::int64_t ulps_apart(float a, float b) {
  std::int32_t ia, ib;
  std::memcpy(&ia, &a, 4);
  std::memcpy(&ib, &b, 4);
  if (ia < 0) ia = std::numeric_limits<std::int32_t>::min() - ia;
  if (ib < 0) ib = std::numeric_limits<std::int32_t>::min() - ib;
  return std::abs(std::int64_t(ia) - std::int64_t(ib));
}

// turn_cos_sin is multiplies and adds only: the GPU's is the float compilation's, bit for bit,
// and within 3e-7 of the host's double (the same polynomials, evaluated in float).
TEST_F(GpuKernels, TurnCosSinIsTheFloatCompilationBitForBit) {
  std::vector<gpu::rng_probe_entry> entries;
  for (std::uint32_t pixel = 0; pixel < 4096; ++pixel)
    entries.push_back({pixel, 0, 1, 0, 0, 0, 0, 0});
  const auto out = gpu::run_rng_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  int differ = 0;
  double worst = 0;
  for (const auto& e : out) {
    const glm::vec2 cpu = f32::turn_cos_sin(e.value);
    differ += !same_bits(e.turn_cos, cpu.x) || !same_bits(e.turn_sin, cpu.y);
    const glm::dvec2 exact = turn_cos_sin(e.value);
    worst = std::max({worst, std::abs(e.turn_cos - exact.x), std::abs(e.turn_sin - exact.y)});
  }
  EXPECT_EQ(differ, 0) << "of " << out.size();
  EXPECT_LE(worst, 3e-7);
}

// get_ray of every camera model. The lens models (perspective, orthographic) are multiplies and
// adds: bit for bit. The panoramic ones take cos, sin and asin, which Vulkan leaves to the device
// (an absolute error of 2^-11 in [-pi, pi] for sin and cos): within 4e-4 of the float
// compilation, to the direction's length (a unit vector).
TEST_F(GpuKernels, GetRayIsTheFloatCompilation) {
  const std::array<glm::vec4, RTVK_PROBE_POINTS> uv = {
      glm::vec4(0, 0, 0, 0), glm::vec4(1, 0.25f, 0, 0), glm::vec4(0.3f, 1, 0, 0),
      glm::vec4(0.9f, 0.6f, 0.6f, -0.3f), glm::vec4(0.5f, 0.5f, -0.25f, 0.5f)};
  for (const char* name : {"perspective", "orthographic", "equirectangular", "fisheye-equidistant",
                           "fisheye-equisolid"}) {
    camera_pose pose;
    pose.lookfrom = point3(13, 2, 3);
    pose.lookat = point3(0, 0, 0);
    pose.vfov = 20;
    pose.projection = *projection_from_name(name);
    pose.aperture = has_lens(pose.projection) ? 0.1 : 0;
    pose.focus_dist = 10;
    pose.fisheye_fov = 200;
    const camera cam(pose, 1.5, 300);
    const gpu::camera_ubo ubo = gpu::to_ubo(cam);
    const gpu::probe_io io = gpu::run_probe(gpu(), cam, uv);
    for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
      SCOPED_TRACE(std::string(name) + ", probe point " + std::to_string(k));
      const f32::ray_f cpu = f32::get_ray(ubo, uv[k].x, uv[k].y, glm::vec2(uv[k].z, uv[k].w));
      for (int c = 0; c < 3; ++c) {
        if (has_lens(pose.projection)) {
          EXPECT_TRUE(same_bits(io.ray_origin[k][c], cpu.origin[c]))
              << io.ray_origin[k][c] << " vs " << cpu.origin[c];
          EXPECT_TRUE(same_bits(io.direction[k][c], cpu.direction[c]))
              << io.direction[k][c] << " vs " << cpu.direction[c];
        } else {
          EXPECT_TRUE(same_bits(io.ray_origin[k][c], cpu.origin[c]));
          EXPECT_NEAR(io.direction[k][c], cpu.direction[c], 4e-4);
        }
      }
    }
  }
}

// A camera a million units from the scene's origin, looking at something near it: the ray
// directions the device forms are the double camera's to float precision (the corner direction
// is formed in double on the host). Formed on the device as lower_left - origin, in float, they
// were up to 0.027 rad off here (measured): the float spacing at 10^6 is 0.0625 units.
TEST_F(GpuKernels, AFarCameraKeepsItsRayDirections) {
  const std::array<glm::vec4, RTVK_PROBE_POINTS> uv = {
      glm::vec4(0, 0, 0, 0), glm::vec4(1, 0.25f, 0, 0), glm::vec4(0.3f, 1, 0, 0),
      glm::vec4(0.9f, 0.6f, 0.6f, -0.3f), glm::vec4(0.5f, 0.5f, -0.25f, 0.5f)};
  camera_pose pose;
  pose.lookfrom = point3(1e6 + 0.3, -1e6 + 0.7, 1e6 + 0.1);
  pose.lookat = pose.lookfrom + vec3(-1, -0.5, -2);
  pose.vfov = 30;
  pose.focus_dist = 2;
  pose.aperture = 0.01;
  const camera cam(pose, 1.5, 300);
  const gpu::probe_io io = gpu::run_probe(gpu(), cam, uv);
  for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
    const ray want = cam.get_ray(uv[k].x, uv[k].y, glm::dvec2(uv[k].z, uv[k].w));
    const glm::dvec3 got = glm::dvec3(glm::vec3(io.direction[k]));
    const double angle = std::acos(
        std::clamp(glm::dot(glm::normalize(got), glm::normalize(want.direction)), -1.0, 1.0));
    EXPECT_LE(angle, 1e-6) << "probe point " << k;
  }
}

// Where the next ray starts, in float as the GPU computes it: every camera ray of book-final
// (160x90, the book's camera 13 units from the origin) that hits a sphere, with the ray leaving
// to the outside (a reflection), must start outside that sphere, measured in double. The offset
// once counted the sphere's extent but not the ray's origin: 25 of 18,496 rays started up to
// 2.8e-6 inside a small sphere with offsets of 1.9e-6 or less (a later ray could hit it again).
TEST(ScatterOrigin, RaysLeavingASphereStartOutsideItHoweverFarTheirOriginWas) {
  const scene s = builtin_scene("book-final");
  for (const point3 eye : {point3(13, 2, 3), point3(130, 20, 30), point3(1300, 200, 300)}) {
    SCOPED_TRACE("eye " + std::to_string(eye.x));
    camera_pose pose = main_camera(s).pose;
    pose.lookfrom = eye;
    pose.vfov = 20 * 13 / eye.x;  // about the same framing
    pose.aperture = 0;
    const camera cam(pose, 16.0 / 9, 160);
    const gpu::camera_ubo ubo = gpu::to_ubo(cam);
    int hits = 0, inside = 0;
    double deepest = 0;
    for (int j = 0; j < cam.image_height(); ++j)
      for (int i = 0; i < cam.image_width(); ++i) {
        const f32::ray_f r = f32::get_ray(ubo, float(i) / (cam.image_width() - 1),
                                          float(j) / (cam.image_height() - 1), glm::vec2(0));
        float closest = 3.4e38f, t = 0;
        const sphere* hit = nullptr;
        for (const sphere& sp : s.spheres)
          if (f32::hit_sphere(glm::vec3(sp.center), float(sp.radius), r, 0.001f, closest, t)) {
            closest = t;
            hit = &sp;
          }
        if (!hit) continue;
        ++hits;
        const glm::vec3 center(hit->center);
        const glm::vec3 p = r.origin + closest * r.direction;
        const glm::vec3 outward = glm::normalize(p - center);
        const glm::vec3 leaving = outward;  // straight out: the scatter's side is the outside
        const glm::vec3 o = f32::scatter_origin(center, float(hit->radius), r, closest, leaving);
        const double depth = hit->radius - glm::length(glm::dvec3(o) - glm::dvec3(center));
        if (depth >= 0) {
          ++inside;
          deepest = std::max(deepest, depth);
        }
      }
    EXPECT_GT(hits, 5000);
    EXPECT_EQ(inside, 0) << "deepest " << deepest;
  }
}

// hit_sphere divides and takes a square root (Vulkan: division within 2.5 ulp, sqrt as the
// reciprocal of inversesqrt): the same hits, and roots within 16 ulp of the float compilation's,
// over random rays into random spheres.
TEST_F(GpuKernels, HitSphereIsTheFloatCompilation) {
  std::mt19937 gen(24);
  std::uniform_real_distribution<float> coord(-20, 20), size(0.05f, 5), unit(-1, 1);
  std::vector<gpu::hit_probe_entry> entries;
  for (int i = 0; i < 4096; ++i) {
    gpu::hit_probe_entry e{};
    e.center = glm::vec3(coord(gen), coord(gen), coord(gen));
    e.radius = size(gen);
    e.origin = glm::vec3(coord(gen), coord(gen), coord(gen));
    // Half aimed near the sphere, half anywhere.
    const glm::vec3 jitter(unit(gen), unit(gen), unit(gen));
    e.direction = i % 2 ? e.center + e.radius * jitter - e.origin : jitter;
    e.t_min = 0.001f;
    e.t_max = i % 3 ? 3.402823466e+38f : 2.0f;
    entries.push_back(e);
  }
  const auto out = gpu::run_hit_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  int hits = 0, exact = 0;
  std::int64_t worst = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& e = entries[i];
    float t = 0;
    const bool hit =
        f32::hit_sphere(e.center, e.radius, {e.origin, e.direction}, e.t_min, e.t_max, t);
    ASSERT_EQ(out[i].hit != 0, hit) << "entry " << i << ": gpu t " << out[i].t << ", cpu t " << t;
    if (!hit) continue;
    ++hits;
    exact += same_bits(out[i].t, t);
    worst = std::max(worst, ulps_apart(out[i].t, t));
  }
  EXPECT_GT(hits, 1000) << "the rays must hit often enough to test the roots";
  EXPECT_LE(worst, 16) << exact << " of " << hits << " roots exact";
}

// scatter for every material, sky_color and the samplers, through run_kernel_probe (the same
// function in the probe shader and in the float compilation), over random hits, arriving rays,
// materials and streams. They take square roots, divide, and (the ball) a cube root, which GLSL
// writes as pow: the same decisions (scattered or absorbed, reflected or refracted), and values
// within 2e-5 of the float compilation's, in units of the value's size (lavapipe: 2.2e-7; Vulkan
// lets a device's pow, behind the cube root, stray much further than its sqrt).
TEST_F(GpuKernels, ScatterSkyAndSamplersAreTheFloatCompilation) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> coord(-10, 10), unit(-1, 1), share(0, 1);
  std::uniform_int_distribution<std::uint32_t> bits;
  const auto unit_vector = [&] {
    for (;;) {
      const glm::vec3 v(unit(gen), unit(gen), unit(gen));
      const float n = glm::length(v);
      if (n > 0.1f && n <= 1) return v / n;
    }
  };
  std::vector<gpu::kernel_probe_entry> entries;
  for (int i = 0; i < 4096; ++i) {
    gpu::kernel_probe_entry e{};
    e.p = glm::vec3(coord(gen), coord(gen), coord(gen));
    e.offset = 1e-5f;
    e.normal = unit_vector();
    e.direction = unit_vector() * (0.5f + 2 * share(gen));
    if (glm::dot(e.direction, e.normal) > 0) e.direction = -e.direction;  // arriving against it
    e.front_face = i % 3 != 0;
    e.type = std::uint32_t(i % 5);  // normal, lambertian, metal, dielectric, flat
    e.albedo = glm::vec3(share(gen), share(gen), share(gen));
    e.fuzz = share(gen);
    e.ir = i % 2 ? 1.5f : 1 / 1.5f;
    e.key = bits(gen);
    e.bounce = 1 + std::uint32_t(i % 7);
    entries.push_back(e);
  }
  const auto out = gpu::run_kernel_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  int scattered = 0;
  double worst = 0;
  const auto apart = [&](const glm::vec3& a, const glm::vec3& b) {
    const double size = std::max(1.0f, std::max({std::abs(b.x), std::abs(b.y), std::abs(b.z)}));
    worst = std::max(worst, double(glm::length(a - b)) / size);
  };
  for (std::size_t i = 0; i < out.size(); ++i) {
    gpu::kernel_probe_entry cpu = entries[i];
    f32::run_kernel_probe(cpu);
    const auto& g = out[i];
    ASSERT_EQ(g.scattered, cpu.scattered) << "entry " << i << ", material " << g.type;
    scattered += int(g.scattered);
    if (g.scattered) {
      apart(g.attenuation, cpu.attenuation);
      apart(g.origin_out, cpu.origin_out);
      apart(g.direction_out, cpu.direction_out);
    }
    apart(g.sky, cpu.sky);
    apart(g.ball, cpu.ball);
    apart(glm::vec3(g.disk_x, g.disk_y, 0), glm::vec3(cpu.disk_x, cpu.disk_y, 0));
  }
  EXPECT_GT(scattered, 2000) << "lambertian, metal and dielectric entries must mostly scatter";
  EXPECT_LE(worst, 2e-5);
}

// A sample's channel as the device adds it to the exact sums (to_fixed and sum_overflows,
// fixed_sum.h, the code render.comp runs), on the values a render rarely makes: NaN (either
// sign), infinities, negatives, -0, subnormals, the limit and past it, and a thousand values from
// 1e-8 to 1e10 (one to three words). NaN, infinities and negatives add 0 and do not overflow
// (render.comp drops and counts the NaN and infinite ones); anything finite past the limit
// overflows (the render fails) and adds 0; the rest add floor(c * 2^42)
// exactly, as the host's integer arithmetic (sample_sum.h) says. Guards are bit tests, not
// comparisons a driver may fold when it assumes no NaN.
TEST_F(GpuKernels, SamplesThatAreNotNumbersOrNotFiniteAddWhatTheRuleSays) {
  const float inf = std::numeric_limits<float>::infinity();
  const float limit = float(RTVK_PROBE_SAMPLE_LIMIT);
  std::vector<float> values{std::numeric_limits<float>::quiet_NaN(),
                            -std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::signaling_NaN(),
                            inf,
                            -inf,
                            -0.0f,
                            0.0f,
                            -1.0f,
                            1e-40f,
                            std::numeric_limits<float>::min(),
                            0x1p-42f,
                            0x1p-43f,
                            0x1.fffffep31f,  // just below 2^32: two full words
                            0x1p32f,
                            0x1.fffffep63f,
                            0x1p64f,  // the top word's first bit (a 1e6 sample's sum reaches it)
                            limit,
                            std::nextafter(limit, inf),
                            1e30f,
                            std::numeric_limits<float>::max()};
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> log_value(-8, 10);
  for (int i = 0; i < 1000; ++i) values.push_back(std::pow(10.0f, log_value(gen)));
  std::vector<gpu::kernel_probe_entry> entries;
  for (float v : values) {
    gpu::kernel_probe_entry e{};
    e.normal = glm::vec3(0, 0, 1);
    e.direction = glm::vec3(0, 0, -1);
    e.sample_value = v;
    entries.push_back(e);
  }
  const auto out = gpu::run_kernel_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  const auto words = [](const gpu::kernel_probe_entry& e) {
    return channel_sum(e.fixed_low, e.fixed_high, e.fixed_top);
  };
  int overflowing = 0, three_words = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const float v = values[i];
    const bool over = std::isfinite(v) && v > limit;
    const exact_sum want = !std::isfinite(v) || std::signbit(v) || over
                               ? 0
                               : exact_sum(std::floor(std::ldexp(double(v), 42)));
    overflowing += over;
    three_words += (want >> 64) != 0;
    EXPECT_TRUE(words(out[i]) == want) << "sample " << v << " (entry " << i << ")";
    EXPECT_EQ(out[i].overflows, over ? 1u : 0u) << "sample " << v;
    EXPECT_TRUE(to_fixed(v, 42) == want && sum_overflows(v, 42) == over) << "sample_sum.h, " << v;
    gpu::kernel_probe_entry cpu = entries[i];
    f32::run_kernel_probe(cpu);
    EXPECT_TRUE(words(cpu) == want) << "float compilation, " << v;
  }
  EXPECT_GE(overflowing, 10);
  EXPECT_GE(three_words, 100);
}

}  // namespace
}  // namespace rtvk
