// The book's features on the GPU: the same random numbers, the same pictures, and no silent
// truncation by lavapipe's loop cap.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <random>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "probe.h"
#include "random.h"
#include "render_gpu.h"
#include "render_helpers.h"
#include "render_plan.h"
#include "scene_file.h"
#include "world.h"

namespace rtvk {
namespace {

class GpuBook : public test::GpuTest {};

TEST_F(GpuBook, RandomNumbersAreBitIdentical) {
  std::vector<gpu::rng_probe_entry> entries;
  for (std::uint32_t pixel : {0u, 1u, 399u, 89999u, 0xffffffffu})
    for (std::uint32_t sample : {0u, 1u, 31u, 499u})
      for (std::uint32_t bounce : {0u, 1u, 2u, 49u})
        for (std::uint32_t dim = 0; dim < 4; ++dim)
          entries.push_back({pixel, sample, bounce, dim, 0, 0, 0, 0});
  const auto out = gpu::run_rng_probe(gpu(), entries);
  ASSERT_EQ(out.size(), entries.size());
  for (const auto& e : out) {
    SCOPED_TRACE(std::to_string(e.pixel) + "/" + std::to_string(e.sample_index) + "/" +
                 std::to_string(e.bounce) + "/" + std::to_string(e.dim));
    ASSERT_EQ(e.bits, random_bits(0x5eed, e.pixel, e.sample_index, e.bounce, e.dim));
    const float cpu = random_float(0x5eed, e.pixel, e.sample_index, e.bounce, e.dim);
    ASSERT_EQ(std::memcmp(&e.value, &cpu, sizeof cpu), 0) << e.value << " vs " << cpu;
  }
}

// The GPU's image against the CPU's, within what lavapipe measured (measured_agreement).
void expect_agreement(gpu::gpu_context& ctx, scene s, int width, int spp, double measured_psnr,
                      double measured_share) {
  s.render.width = width;
  s.render.spp = spp;
  const image_rgb8 cpu = test::cpu_image(s);
  const image_difference d =
      compare_images(test::gpu_image(ctx, s), cpu, monte_carlo_agreement.tolerance);
  const agreement rule =
      test::measured_agreement(measured_psnr, measured_share, cpu.width * cpu.height);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db) << s.name;
  EXPECT_LE(d.share_over, rule.max_share)
      << s.name << ": " << d.pixels_over << " pixels over 2 levels";
}

// Measured: 80.0 dB, 1 pixel over 2 levels of 22,400.
TEST_F(GpuBook, MaterialsSceneMatchesTheCpu) {
  expect_agreement(gpu(), builtin_scene("materials"), 200, 32, 80.0, 4.5e-5);
}

// Measured: 58.6 dB, 163 pixels (0.24%) over 2 levels.
TEST_F(GpuBook, BookFinalMatchesTheCpu) {
  expect_agreement(gpu(), builtin_scene("book-final"), 320, 8, 58.6, 0.0024);
}

// The second book's constant background: every ray that misses gathers exactly that color on
// the CPU (double) and exactly its float on the GPU (the exact sums add a float's bits without
// rounding), in every direction. The sky's blend of two equal colors rounds some by an ulp.
TEST_F(GpuBook, ABackgroundIsExactlyItsColorWhereRaysMiss) {
  scene s = parse_scene_json(
      R"({"background":[0.3,0.6,0.9],"render":{"gamma":1,"width":64,"aspect":2,"spp":2,"jitter":true},)"
      R"("camera":{"lookfrom":[0,0,0],"lookat":[0,0,-1],"vfov":120},)"
      R"("materials":{"m":{"type":"flat","albedo":[1,0,0]}},)"
      R"("spheres":[{"center":[0,0,-2],"radius":0.5,"material":"m"}]})",
      "background.json");
  const camera cam = test::scene_camera(s);
  const framebuffer cpu = render_cpu(cam, s, s.render);
  const framebuffer gpu_fb = gpu::render_gpu(gpu(), cam, s, s.render);
  const color want(0.3, 0.6, 0.9);
  const color want_float(double(float(0.3)), double(float(0.6)), double(float(0.9)));
  int missed = 0;
  for (int y = 0; y < cpu.height(); ++y)
    for (int x = 0; x < cpu.width(); ++x) {
      const double red = cpu.at(x, y).x;
      if (red == 1 || red == (1 + 0.3) / 2) continue;  // the sphere's, or half its, half not
      ++missed;
      EXPECT_EQ(cpu.at(x, y), want) << "cpu pixel " << x << "," << y;
      EXPECT_EQ(gpu_fb.at(x, y), want_float) << "gpu pixel " << x << "," << y;
    }
  EXPECT_GT(missed, 1500);
  EXPECT_NE(dump_scene_json(s).find("\"background\": [0.3,0.6,0.9]"), std::string::npos);
}

// The flat material, written once (shaders/shared/ray_color.h), draws its albedo where it is
// seen, unlit, through a metal mirror too (the throughput times the albedo), on both backends:
// a deterministic image, so both give the same bytes.
TEST_F(GpuBook, AFlatMaterialIsItsAlbedoOnBothBackends) {
  scene s;
  s.name = "flat test";
  s.materials = {{"flat", {material_type::flat, color(0.8, 0.3, 0.1), 0, 1.5}},
                 {"mirror", {material_type::metal, color(0.5, 0.5, 0.5), 0, 1.5}},
                 {"normal", {}}};
  s.spheres = {sphere(point3(0, 0, -1), 0.5, 0), sphere(point3(0, -100.5, -1), 100, 2),
               sphere(point3(-0.9, 0, -1), 0.3, 1)};
  s.render.width = 64;
  const camera cam = test::scene_camera(s);
  const framebuffer cpu = render_cpu(cam, s, s.render);
  const framebuffer gpu_fb = gpu::render_gpu(gpu(), cam, s, s.render);
  const int cx = cam.image_width() / 2, cy = cam.image_height() / 2;
  EXPECT_EQ(cpu.at(cx, cy), color(0.8, 0.3, 0.1));  // exactly the albedo, no light, no bounce
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(gpu_fb.at(cx, cy)[c], cpu.at(cx, cy)[c], 1e-6);
  // Seen in the mirror (left), the flat sphere is its albedo times the mirror's.
  int mirrored = 0;
  for (int x = 0; x < cx; ++x)
    for (int y = 0; y < cam.image_height(); ++y)
      mirrored += glm::length(cpu.at(x, y) - color(0.4, 0.15, 0.05)) < 1e-12;
  EXPECT_GT(mirrored, 0) << "no pixel of the mirror shows the flat sphere";
  EXPECT_EQ(test::cpu_image(s, cam).rgb, test::gpu_image(gpu(), s, cam).rgb);
}

TEST_F(GpuBook, SeedImageIsStillTheReference) {
  const scene s = builtin_scene("seed");
  const image_difference d = compare_images(test::gpu_image(gpu(), s), test::cpu_image(s), 1);
  EXPECT_LE(d.share_over, 0.001);
}

TEST_F(GpuBook, LoopBudgetOverrunFailsTheRenderInsteadOfTruncating) {
  scene s = builtin_scene("materials");
  s.render.width = 32;
  s.render.spp = 2;
  const camera cam = test::scene_camera(s);
  // 5 spheres and up to 50 bounces: far more than 20 iterations for most pixels.
  try {
    gpu::render_gpu(gpu(), cam, s, s.render, {},
                    gpu::gpu_render_options{.engine = {.use_bvh = false}, .loop_budget = 20});
    FAIL() << "no loop_budget_error";
  } catch (const gpu::loop_budget_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("more than 20 loop iterations"), std::string::npos) << what;
    EXPECT_NE(what.find(gpu().device().name), std::string::npos) << what;
  }
  // The same render within budget succeeds.
  EXPECT_NO_THROW(gpu::render_gpu(
      gpu(), cam, s, s.render, {},
      gpu::gpu_render_options{.engine = {.use_bvh = false}, .loop_budget = 100000}));
}

// One pixel looking down -z at a sphere listed after `hidden` spheres behind the camera. With
// --accel none its one path costs an iteration for the bounce and one per sphere tested, so
// hidden + 2 in all, and only the last test finds the sphere: a loop cut short sees the sky.
scene last_sphere_seen_after(int hidden) {
  scene s;
  s.materials = {{"normal", material{}}};
  for (int i = 0; i < hidden; ++i)
    s.spheres.push_back(sphere(point3(i % 256, i / 256, 10), 0.4, 0));
  s.spheres.push_back(sphere(point3(0, 0, -1), 0.5, 0));
  s.render.width = 1;
  s.render.aspect = 1;
  return s;
}

// The highest loop budget is the device's (pacer.h): 60,000 where the driver stops loops
// (loop_limited, by driver ID: lavapipe, which would silently cut a path at 65,535 trips and
// return the sky), so the path past it fails the render there; 2^30 elsewhere, where it renders
// the sphere. Below 60,000 it renders everywhere.
TEST_F(GpuBook, DefaultBudgetFailsWhatALoopLimitedDeviceWouldTruncateAndRendersTheRest) {
  const engine_options linear{.use_bvh = false};  // the default loop budget
  const bool limited = gpu::loop_limited(gpu().device());
  for (int hidden : {50'000, 70'000}) {
    SCOPED_TRACE(std::to_string(hidden) + " spheres behind the camera on " + gpu().device().name);
    const scene s = last_sphere_seen_after(hidden);
    const camera cam = test::scene_camera(s);
    // Head on: normal (0, 0, 1), shaded (0.5, 0.5, 1).
    const color want = render_cpu(cam, s, s.render, {}, linear).at(0, 0);
    ASSERT_EQ(want, color(0.5, 0.5, 1));
    if (limited && hidden > 65'535) {
      // The budget (60,000, below the driver's cap) stops the path first and fails the render.
      try {
        const color got = gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = linear}).at(0, 0);
        ADD_FAILURE() << "no loop_budget_error; the pixel came back (" << got.r << ", " << got.g
                      << ", " << got.b << "), the sphere's color is (0.5, 0.5, 1)";
      } catch (const gpu::loop_budget_error& e) {
        EXPECT_NE(std::string(e.what()).find("more than 60000 loop iterations"), std::string::npos)
            << e.what();
      }
    } else {
      // The path runs to its end (under a budget raised from the first as far as it needs).
      const color got = gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = linear}).at(0, 0);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-6) << "channel " << k;
    }
  }
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

// The BVH and the thread count change how fast an image is made, never the image.
TEST(Accel, BvhAndThreadsGiveTheIdenticalCpuImage) {
  for (const char* name : {"seed", "materials", "book-final"}) {
    const scene s = test::small_scene(name, 96, 3);
    const camera cam = test::scene_camera(s);
    auto image = [&](engine_options e) { return quantize(render_cpu(cam, s, s.render, {}, e), 2); };
    const image_rgb8 reference = image({.use_bvh = false, .threads = 1});
    EXPECT_EQ(image({.use_bvh = true, .threads = 1}).rgb, reference.rgb) << name;
    EXPECT_EQ(image({.use_bvh = true, .threads = 3}).rgb, reference.rgb) << name;
    EXPECT_EQ(image({.use_bvh = false, .threads = 2}).rgb, reference.rgb) << name;
  }
}

TEST(Accel, CoincidentSpheresBreakTiesLikeTheLinearScan) {
  // Two spheres in exactly the same place with different materials: the later one must win,
  // whatever order the BVH visits them in.
  scene s = builtin_scene("seed");
  s.materials.push_back({"red", {material_type::lambertian, color(1, 0, 0), 0, 1.5}});
  for (int i = 0; i < 9; ++i) s.spheres.push_back(sphere(point3(0.3 * i - 1.2, 0.6, -2), 0.2, 0));
  s.spheres.push_back(sphere(point3(0, 0, -1), 0.5, 1));  // covers the seed's ball exactly
  s.render.width = 64;
  const camera cam = test::scene_camera(s);
  const image_rgb8 linear = quantize(render_cpu(cam, s, s.render, {}, {.use_bvh = false}));
  EXPECT_EQ(quantize(render_cpu(cam, s, s.render, {}, {.use_bvh = true})).rgb, linear.rgb);
}

TEST_F(GpuBook, BvhGivesTheIdenticalGpuImage) {
  for (const char* name : {"seed", "materials", "book-final"}) {
    const scene s = test::small_scene(name, 96, 3);
    const camera cam = test::scene_camera(s);
    auto image = [&](bool bvh) {
      return quantize(gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = {.use_bvh = bvh}}),
                      2);
    };
    EXPECT_EQ(image(true).rgb, image(false).rgb) << name;
  }
}

// Where one source cannot serve: the CPU walks a four-wide tree with SSE, in double; the GPU the
// binary tree in a flat loop, in float. On the same rays (book-final's camera rays, and rays
// from random points in random directions, the float rays given to both) they must find the
// same closest hits: the same material, the same surface to within float rounding, the normal to
// 1e-3. Only a ray that grazes a sphere's edge may go either way, where float and double round
// the discriminant differently. The GPU's own two searches, through the BVH and over every
// sphere, agree bit for bit.
// Rays that are not numbers or not finite (a degenerate camera, an overflowed bounce) hit
// nothing, on both traversals of the GPU and on the CPU: the shared kernels test finiteness by
// bits (is_finite) instead of counting on NaN failing comparisons, which a driver may fold away.
TEST_F(GpuBook, NanAndInfiniteRaysHitNothingOnEitherBackend) {
  const scene s = builtin_scene("book-final");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const glm::vec3 o(13, 2, 3), d(-13, -2, -3);  // the book's camera, looking at the origin
  const std::vector<std::pair<glm::vec3, glm::vec3>> rays{
      {o, glm::vec3(nan, -2, -3)}, {o, glm::vec3(nan)},  {o, glm::vec3(-inf, -2, -3)},
      {o, glm::vec3(-inf)},        {o, glm::vec3(0)},    {glm::vec3(nan, 2, 3), d},
      {glm::vec3(inf, 2, 3), d},   {glm::vec3(-inf), d}, {o, glm::vec3(-1e-30f, 0, 0)},
  };
  std::vector<gpu::world_probe_entry> entries;
  for (const auto& [origin, direction] : rays) {
    gpu::world_probe_entry e{};
    e.origin = origin;
    e.direction = direction;
    entries.push_back(e);
  }
  // A finite ray last, so a probe that hit nothing at all would show.
  entries.push_back(entries.back());
  entries.back().origin = o;
  entries.back().direction = d;
  const std::unique_ptr<hittable> cpu = make_accelerated_world(s, true);
  for (const bool bvh : {true, false}) {
    SCOPED_TRACE(bvh ? "BVH" : "every sphere");
    const auto got = gpu::run_world_probe(gpu(), s, bvh, entries);
    for (std::size_t k = 0; k + 1 < entries.size(); ++k) {
      EXPECT_EQ(got[k].hit, 0u) << "ray " << k << " hit at t = " << got[k].t;
      // A search ends within a visit of each node and sphere (lavapipe 22.3 would stop an
      // endless one silently at 65,535 trips; Mesa 25 hangs): an origin at infinity once sent
      // the four-wide walk round the tree for ever.
      EXPECT_LE(got[k].iterations, 2 * s.spheres.size()) << "ray " << k;
      hit_record rec{};
      const ray r(vec3(entries[k].origin), vec3(entries[k].direction));
      EXPECT_FALSE(cpu->hit(r, 0.001, std::numeric_limits<double>::infinity(), rec))
          << "ray " << k << " on the CPU";
    }
    EXPECT_EQ(got.back().hit, 1u) << "the finite ray";
  }
}

TEST_F(GpuBook, BothTraversalsFindTheSameClosestHits) {
  const scene s = builtin_scene("book-final");
  const camera cam(main_camera(s).pose, 16.0 / 9.0, 160);
  std::vector<gpu::world_probe_entry> entries;
  const auto add = [&](const ray& r) {
    gpu::world_probe_entry e{};
    e.origin = glm::vec3(r.origin);
    e.direction = glm::vec3(r.direction);
    entries.push_back(e);
  };
  for (int j = 0; j < cam.image_height(); ++j)
    for (int i = 0; i < cam.image_width(); ++i)
      add(cam.get_ray(pixel_coordinate(i, uint(cam.image_width())),
                      pixel_coordinate(j, uint(cam.image_height()))));
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> box(-12, 12), height(0, 3), unit(-1, 1);
  for (int k = 0; k < 4096; ++k)
    add(ray(point3(box(gen), height(gen), box(gen)), vec3(unit(gen), unit(gen), unit(gen))));

  const auto gpu_bvh = gpu::run_world_probe(gpu(), s, true, entries);
  const auto gpu_scan = gpu::run_world_probe(gpu(), s, false, entries);
  const std::unique_ptr<hittable> cpu = make_accelerated_world(s, true);
  int hits = 0, differ = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    SCOPED_TRACE("ray " + std::to_string(k));
    ASSERT_EQ(gpu_bvh[k].hit, gpu_scan[k].hit);
    ASSERT_EQ(gpu_bvh[k].t, gpu_scan[k].t);
    ASSERT_EQ(gpu_bvh[k].material, gpu_scan[k].material);
    hit_record rec{};
    const ray r(vec3(entries[k].origin), vec3(entries[k].direction));
    const bool hit = cpu->hit(r, 0.001, std::numeric_limits<double>::infinity(), rec);
    hits += hit;
    const auto& g = gpu_bvh[k];
    // The GPU's hit point off the CPU's surface (along its normal) by no more than float rounding
    // of origin + t * direction: 2^-20 of the largest coordinate involved, the sphere's extent
    // (the scatter offset) or the ray's origin. Along the surface a grazing ray's point may slide
    // further. (The scatter offset alone leaves out the origin: 25 of these camera rays, from 13
    // units away, land up to 2.8e-6 off spheres whose offset is 1.9e-6 or less.)
    const double origin_extent =
        std::max({std::abs(r.origin.x), std::abs(r.origin.y), std::abs(r.origin.z)});
    const bool same =
        (g.hit != 0) == hit && (!hit || (g.material == rec.material &&
                                         std::abs(glm::dot(ray_at(r, g.t) - rec.p, rec.normal)) <=
                                             rec.offset + origin_extent * 0x1p-20 &&
                                         glm::length(vec3(g.normal) - rec.normal) <= 1e-3));
    differ += !same;
  }
  EXPECT_GT(hits, int(entries.size()) / 2);
  // 18,496 rays; a grazing ray's fate is a matter of rounding: 0 differ on lavapipe (Mesa 22.3),
  // a few would be no fault.
  EXPECT_LE(differ, int(entries.size()) / 1000) << "of " << entries.size() << " rays";
}

TEST_F(GpuBook, RayCountsAgreeWithTheCpu) {
  scene s = builtin_scene("book-final");
  s.render.width = 64;
  s.render.spp = 2;
  const camera cam = test::scene_camera(s);
  render_stats cpu, gpu_stats;
  render_cpu(cam, s, s.render, {}, {.count_rays = true}, &cpu);
  gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = {.count_rays = true}}, &gpu_stats);
  // At least one ray per sample; the same paths up to float divergence.
  EXPECT_GE(cpu.rays, 64u * 42 * 2);
  EXPECT_NEAR(double(gpu_stats.rays), double(cpu.rays), 0.01 * double(cpu.rays));
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

TEST_F(GpuBook, BandsOfRowsJoinWithoutASeam) {
  // Images larger than one storage buffer are rendered in bands; force bands of 5 rows on a small
  // image and require the very same bytes as one band.
  for (const char* name : {"seed", "materials"}) {
    const scene s = test::small_scene(name, 97, 3);
    const camera cam = test::scene_camera(s);
    auto image = [&](std::uint64_t band_bytes) {
      render_stats stats;
      gpu::gpu_render_options e;
      e.band_bytes = band_bytes;
      e.engine.count_rays = true;
      const image_rgb8 img = quantize(gpu::render_gpu(gpu(), cam, s, s.render, {}, e, &stats), 2);
      return std::pair(img, stats.rays);
    };
    const auto [whole, whole_rays] = image(0);
    const auto [banded, banded_rays] = image(97 * 12 * 5);
    EXPECT_EQ(banded.rgb, whole.rgb) << name;
    EXPECT_EQ(banded_rays, whole_rays) << name;
  }
}

}  // namespace
}  // namespace rtvk
