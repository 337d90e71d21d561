// One GPU engine per run: the scene is set up once and serves every view, window, sample range
// and settings a run asks for, each image bit for bit what a fresh set-up gives.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "gpu_engine.h"
#include "gpu_fixture.h"
#include "render_helpers.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

class GpuEngine : public test::GpuTest {};

TEST_F(GpuEngine, OneSetUpServesEveryRenderOfARunAsFreshSetUpsWould) {
  scene s = test::small_scene("book-final", 48, 3);
  s.render.max_depth = 8;
  const camera book = test::scene_camera(s);
  camera_pose side_pose = main_camera(s).pose;
  side_pose.lookfrom = point3(-8, 3, 6);
  const camera side(side_pose, s.render.aspect, s.render.width);
  const int w = book.image_width(), h = book.image_height();
  render_settings other_seed = s.render;
  other_seed.seed = 7;
  other_seed.jitter = !other_seed.jitter;
  struct request {
    std::vector<camera> views;
    render_settings rs;
    render_window win;
  };
  // Small, then larger (the targets grow), more views, a region, a sample range, other settings.
  const std::vector<request> requests{
      {{book}, s.render, {0, 0, 8, 4, 0, 2}},          {{book}, s.render, whole_render(w, h, 3)},
      {{book, side}, s.render, whole_render(w, h, 3)}, {{side}, s.render, {5, 3, 20, 9, 1, 3}},
      {{book}, other_seed, whole_render(w, h, 2)},
  };
  gpu::gpu_engine engine(gpu(), s);
  EXPECT_GT(engine.setup_seconds(), 0);
  for (std::size_t k = 0; k < requests.size(); ++k) {
    const request& q = requests[k];
    render_stats st;
    const auto got = engine.render_views(q.views, q.rs, q.win, {}, &st);
    const auto want = gpu::render_gpu_views(gpu(), q.views, s, q.rs, q.win);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t v = 0; v < got.size(); ++v)
      EXPECT_TRUE(test::same_pixels(got[v], want[v])) << "request " << k << ", view " << v;
    EXPECT_GE(st.submissions, 1) << "request " << k;
  }
  // The guard: the requests really draw different pictures.
  const auto a = engine.render_views({book}, s.render, whole_render(w, h, 3));
  const auto b = engine.render_views({side}, s.render, whole_render(w, h, 3));
  EXPECT_FALSE(test::same_pixels(a[0], b[0]));
}

// The viewer's accumulation stays on the device: passes of samples over bands of rows, in any
// split, added to sums the engine keeps (no readback, no clear between calls) and encoded there,
// give the bytes one render of all the samples encodes; a pass from sample 0 starts its rows
// afresh (what was there before does not show); rays are counted on the device.
TEST_F(GpuEngine, AnImageAccumulatedOnTheDeviceIsTheEncodedRendersBytes) {
  const scene s = test::small_scene("book-final", 64, 6);
  const camera cam = test::scene_camera(s);
  const int w = cam.image_width(), h = cam.image_height();
  gpu::gpu_engine engine(gpu(), s, {.engine = {.count_rays = true}});
  const image_rgb8 want = engine.render_encoded({cam}, s.render, whole_render(w, h, 6))[0];
  engine.reset_accumulation(w, h);
  for (const std::uint8_t v : engine.read_accumulation(w, h).rgb) ASSERT_EQ(v, 0) << "not black";
  // Something else first, from another camera: the passes from sample 0 replace it.
  camera_pose aside = main_camera(s).pose;
  aside.lookfrom = point3(0, 10, 1);
  engine.accumulate(camera(aside, s.render.aspect, w), s.render, {0, 0, w, h, 0, 2});
  struct pass {
    int from, to;           // samples
    std::vector<int> rows;  // band boundaries
  };
  render_stats stats;
  std::uint64_t rays = 0;
  for (const pass& p : {pass{0, 1, {0, 10, h}}, pass{1, 3, {0, h}}, pass{3, 6, {0, 7, 8, 30, h}}})
    for (std::size_t k = 0; k + 1 < p.rows.size(); ++k) {
      engine.accumulate(cam, s.render, {0, p.rows[k], w, p.rows[k + 1] - p.rows[k], p.from, p.to},
                        &stats);
      rays += stats.rays;
    }
  const image_rgb8 got = engine.read_accumulation(w, h);
  EXPECT_TRUE(got.rgb == want.rgb) << "max difference " << compare_images(got, want, 0).max_abs;
  EXPECT_GE(rays, std::uint64_t(w) * h * 6) << "every sample traces a ray at least";
}

TEST_F(GpuEngine, DeviceTimeIsMeasuredWithinTheRendersOwnTime) {
  const scene s = test::small_scene("materials", 64, 4);
  const camera cam = test::scene_camera(s);
  gpu::gpu_engine engine(gpu(), s);
  render_stats st;
  const auto start = std::chrono::steady_clock::now();
  engine.render_views({cam}, s.render, whole_render(cam.image_width(), cam.image_height(), 4), {},
                      &st);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (gpu().device().driver_name == "llvmpipe") {  // lavapipe's queue has timestamps
    EXPECT_GT(gpu().device().timestamp_valid_bits, 0u);
  }
  if (gpu().device().timestamp_valid_bits == 0) {
    EXPECT_EQ(st.gpu_seconds, 0);
    return;
  }
  EXPECT_GT(st.gpu_seconds, 0);
  EXPECT_LE(st.gpu_seconds, wall) << "device time is part of the render's wall time";
}

// The camera inside a closed grey sphere: no path escapes, so a path runs to its depth and its
// loop iterations grow with it (one for the bounce, one for the sphere test).
scene inside_a_sphere() {
  scene s;
  s.name = "inside";
  s.materials = {{"grey", material{material_type::lambertian, color(0.5), 0, 1.5}}};
  s.spheres = {sphere(point3(0, 0, 0), 10, 0)};
  s.render.width = 2;
  s.render.aspect = 1;
  return s;
}

TEST_F(GpuEngine, AnOverrunInOneRenderDoesNotFailTheNext) {
  const scene s = inside_a_sphere();
  const camera cam = test::scene_camera(s);
  gpu::gpu_engine engine(gpu(), s, {.engine = {.use_bvh = false}, .loop_budget = 20});
  render_settings deep = s.render;
  deep.max_depth = 50;
  EXPECT_THROW(engine.render_views({cam}, deep, whole_render(2, 2, 1)), gpu::loop_budget_error);
  render_settings shallow = s.render;
  shallow.max_depth = 2;  // a handful of iterations: within the budget
  const auto fbs = engine.render_views({cam}, shallow, whole_render(2, 2, 1));
  const auto fresh = gpu::render_gpu_views(gpu(), {cam}, s, shallow, whole_render(2, 2, 1), {},
                                           {.engine = {.use_bvh = false}, .loop_budget = 20});
  EXPECT_TRUE(test::same_pixels(fbs[0], fresh[0]));
}

// A BVH walk that finds its stack full stops and drops its sample (added black, counted), never
// a write past the stack or a wrong hit. The builder's depth cap keeps every real tree within the
// shader's stack, so the test lets the walk use only 2 of its entries (RTVK_SPEC_STACK): book-
// final's 485 spheres need more, and the overflows are counted in the status and the stats (in
// the dropped samples too). With the whole stack, none is.
TEST_F(GpuEngine, AFullBvhStackDropsTheSampleAndCountsIt) {
  const scene s = test::small_scene("book-final", 16, 2);
  const camera cam = test::scene_camera(s);
  const render_window win = whole_render(cam.image_width(), cam.image_height(), 2);
  render_stats tiny, whole;
  gpu::gpu_engine cramped(gpu(), s, {.stack_entries = 2});
  cramped.render_views({cam}, s.render, win, {}, &tiny);
  EXPECT_GT(tiny.stack_overflows, 0u);
  EXPECT_GE(tiny.dropped_samples, tiny.stack_overflows);
  EXPECT_LE(tiny.stack_overflows, std::uint64_t(cam.image_width()) * cam.image_height() * 2);
  gpu::gpu_engine roomy(gpu(), s, {});
  roomy.render_views({cam}, s.render, win, {}, &whole);
  EXPECT_EQ(whole.stack_overflows, 0u);
  EXPECT_EQ(whole.dropped_samples, 0u);
}

gpu::gpu_render_options cached_in(const std::filesystem::path& folder) {
  gpu::gpu_render_options o;
  o.pipeline_cache_folder = folder;
  return o;
}

std::vector<framebuffer> seed_views(gpu::gpu_engine& engine, const scene& s) {
  const camera cam = test::scene_camera(s);
  return engine.render_views({cam}, s.render,
                             whole_render(cam.image_width(), cam.image_height(), s.render.spp));
}

TEST_F(GpuEngine, PipelinesAreKeptBetweenRunsInTheCacheFolder) {
  test::temp_dir dir;
  const scene s = test::small_scene("seed", 32, 1);
  const gpu::gpu_render_options options = cached_in(dir.path());
  gpu::gpu_engine first(gpu(), s, options);
  EXPECT_EQ(first.cache().loaded_bytes(), 0u) << "nothing to load in a new folder";
  const framebuffer image = seed_views(first, s)[0];  // builds the pipeline
  ASSERT_TRUE(std::filesystem::is_regular_file(first.cache().file()));
  EXPECT_EQ(first.cache().file().parent_path(), dir.path());
  // At least the 32-byte header naming the device (lavapipe keeps no code in its cache: only
  // that); a real GPU's driver adds its compiled code.
  const auto size = std::filesystem::file_size(first.cache().file());
  EXPECT_GE(size, 32u);
  gpu::gpu_engine second(gpu(), s, options);
  EXPECT_EQ(second.cache().loaded_bytes(), size - gpu::pipeline_cache::header_bytes)
      << "the second engine starts from the file";
  EXPECT_EQ(second.cache().ignored_because(), "");
  EXPECT_TRUE(test::same_pixels(seed_views(second, s)[0], image));
}

TEST_F(GpuEngine, AForeignOrBrokenCacheFileIsIgnoredAndReplaced) {
  test::temp_dir dir;
  const scene s = test::small_scene("seed", 32, 1);
  const gpu::gpu_render_options options = cached_in(dir.path());
  const std::filesystem::path file = gpu::gpu_engine(gpu(), s, options).cache().file();
  const framebuffer want = gpu::render_gpu_views(gpu(), {test::scene_camera(s)}, s, s.render,
                                                 whole_render(32, 18, 1))[0];
  // Another device's header (vendor 0xdead), then bytes that are no cache at all.
  std::vector<std::uint32_t> foreign(64, 0);
  foreign[0] = 32, foreign[1] = 1, foreign[2] = 0xdead, foreign[3] = 0xbeef;
  for (const std::string& bytes :
       {std::string(reinterpret_cast<const char*>(foreign.data()), foreign.size() * 4),
        std::string(1000, '\x5a'), std::string()}) {
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    gpu::gpu_engine engine(gpu(), s, options);
    EXPECT_EQ(engine.cache().loaded_bytes(), 0u) << bytes.size() << " bytes offered";
    EXPECT_TRUE(test::same_pixels(seed_views(engine, s)[0], want));
    EXPECT_GE(gpu::gpu_engine(gpu(), s, options).cache().loaded_bytes(), 32u)
        << "the file was written anew";
  }
}

// rtvk's header guards the driver from data it might crash on (lavapipe keeps only Vulkan's
// header, so without rtvk's own check a damaged file would never be noticed here): a file cut
// short, a flipped byte, another driver version -- each ignored, saying why, and written anew.
TEST_F(GpuEngine, ATruncatedCorruptedOrStaleCacheFileIsIgnoredSayingWhy) {
  test::temp_dir dir;
  const scene s = test::small_scene("seed", 32, 1);
  const gpu::gpu_render_options options = cached_in(dir.path());
  gpu::gpu_engine first(gpu(), s, options);
  const framebuffer want = seed_views(first, s)[0];
  const std::filesystem::path file = first.cache().file();
  std::string good;
  {
    std::ifstream in(file, std::ios::binary);
    good.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(good.size(), gpu::pipeline_cache::header_bytes);
  EXPECT_EQ(good.substr(0, 7), "rtvkpc1");
  struct damage {
    const char* what;
    std::string bytes;
    const char* reason;
  };
  std::string flipped = good, stale = good;
  flipped.back() = char(flipped.back() ^ 0x40);
  stale[32] = char(stale[32] ^ 1);  // the driver version, in rtvk's header
  const std::vector<damage> damages{
      {"one byte short", good.substr(0, good.size() - 1), "truncated or extended"},
      {"header only", good.substr(0, 40), "shorter than its header"},
      {"a flipped bit", flipped, "corrupted"},
      {"another driver version", stale, "made by another device or driver"},
  };
  for (const damage& d : damages) {
    SCOPED_TRACE(d.what);
    std::ofstream(file, std::ios::binary | std::ios::trunc) << d.bytes;
    gpu::gpu_engine engine(gpu(), s, options);
    EXPECT_EQ(engine.cache().loaded_bytes(), 0u);
    EXPECT_NE(engine.cache().ignored_because().find(d.reason), std::string::npos)
        << engine.cache().ignored_because();
    EXPECT_TRUE(test::same_pixels(seed_views(engine, s)[0], want));
    gpu::gpu_engine again(gpu(), s, options);
    EXPECT_EQ(again.cache().ignored_because(), "") << "written anew";
    EXPECT_GT(again.cache().loaded_bytes(), 0u);
  }
}

TEST_F(GpuEngine, ACacheFolderThatCannotBeWrittenOnlyCostsTime) {
  test::temp_dir dir;
  std::ofstream(dir.path() / "taken") << "a file where the folder would go";
  const scene s = test::small_scene("seed", 32, 1);
  gpu::gpu_engine engine(gpu(), s, cached_in(dir.path() / "taken" / "rtvk"));
  EXPECT_FALSE(engine.cache().save());
  EXPECT_EQ(seed_views(engine, s)[0].width(), 32);
}

}  // namespace
}  // namespace rtvk
