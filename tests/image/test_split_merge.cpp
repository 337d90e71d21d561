// A render split by tile and by sample range, on either backend, and merged back: tiles give the
// whole render bit for bit; sample ranges give it to float-summation tolerance. Also the merge's
// refusals: overlapping pieces, missing pixels or samples, pieces of another render.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "errors.h"
#include "gpu_fixture.h"
#include "image_io.h"
#include "merge.h"
#include "partial_image.h"
#include "render_helpers.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

// book-final small: jittered pixels, a lens, all three materials.
scene split_scene() {
  scene s = test::small_scene("book-final", 61, 8);
  s.render.max_depth = 8;
  return s;
}

using window_renderer = std::function<framebuffer(const render_window&)>;

named_partial piece(const scene& s, const camera& cam, const render_window& w,
                    const window_renderer& draw) {
  partial_image p = make_partial(draw(w), {cam.image_width(),
                                           cam.image_height(),
                                           w,
                                           {},
                                           s.render.gamma,
                                           "test",
                                           "",
                                           "",
                                           0,
                                           "1.0",
                                           "s"});
  return {"piece " + std::to_string(w.x) + "," + std::to_string(w.y) + " " +
              std::to_string(w.sample_begin),
          std::move(p)};
}

// Through the OpenEXR file and back, as on a render farm.
named_partial through_file(const named_partial& p, const test::temp_dir& dir) {
  const auto path = dir.path() / "piece.exr";
  write_partial_exr(p.image, path);
  return {p.file, read_partial_exr(path)};
}

void tiles_equal_the_whole(const scene& s, const window_renderer& draw) {
  const camera cam = test::scene_camera(s);
  const int w = cam.image_width(), h = cam.image_height(), n = s.render.spp;
  test::temp_dir dir;
  const named_partial whole = through_file(piece(s, cam, whole_render(w, h, n), draw), dir);
  // Uneven tiles: a 2x2 grid split off-center.
  const int cx = w / 3, cy = h / 2 + 1;
  std::vector<named_partial> tiles;
  for (const render_window& t :
       {render_window{0, 0, cx, cy, 0, n}, render_window{cx, 0, w - cx, cy, 0, n},
        render_window{0, cy, cx, h - cy, 0, n}, render_window{cx, cy, w - cx, h - cy, 0, n}})
    tiles.push_back(through_file(piece(s, cam, t, draw), dir));
  const merged_render m = merge_partials(tiles);
  EXPECT_EQ(m.summary.window, whole.image.window);
  std::size_t differ = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        differ += float(m.fb.at(x, y)[c]) != whole.image.rgb[(std::size_t(y) * w + x) * 3 + c];
  EXPECT_EQ(differ, 0u) << "channels that differ between the merged tiles and the whole render";
  EXPECT_EQ(quantize(m.fb, s.render.gamma).rgb,
            quantize(merge_partials({whole}).fb, s.render.gamma).rgb);
}

void sample_halves_equal_the_whole(const scene& s, const window_renderer& draw, double tolerance) {
  const camera cam = test::scene_camera(s);
  const int w = cam.image_width(), h = cam.image_height(), n = s.render.spp;
  const named_partial whole = piece(s, cam, whole_render(w, h, n), draw);
  const merged_render m = merge_partials(
      {piece(s, cam, {0, 0, w, h, 0, 3}, draw), piece(s, cam, {0, 0, w, h, 3, n}, draw)});
  EXPECT_EQ(m.summary.window, whole.image.window);
  double worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double a = m.fb.at(x, y)[c], b = whole.image.rgb[(std::size_t(y) * w + x) * 3 + c];
        worst = std::max(worst, std::abs(a - b) / std::max(1.0, std::abs(b)));
      }
  EXPECT_LE(worst, tolerance);
  EXPECT_GT(worst, 0) << "the halves were not summed apart: the test proves nothing";
}

window_renderer on_cpu(const scene& s) {
  return [s](const render_window& w) {
    return render_cpu_window(test::scene_camera(s), s, s.render, w);
  };
}

TEST(SplitMerge, CpuTilesEqualTheWholeRenderExactly) {
  const scene s = split_scene();
  tiles_equal_the_whole(s, on_cpu(s));
}

TEST(SplitMerge, CpuSampleHalvesEqualTheWholeRender) {
  const scene s = split_scene();
  // Means of 3 and 5 samples, rounded to float and re-weighted, against the mean of 8.
  sample_halves_equal_the_whole(s, on_cpu(s), 1e-6);
}

class GpuSplitMerge : public test::GpuTest {
 protected:
  window_renderer on_gpu(const scene& s, gpu::gpu_render_options engine = {}) {
    return [this, s, engine](const render_window& w) {
      return gpu::render_gpu_views(gpu(), {test::scene_camera(s)}, s, s.render, w, {}, engine)
          .front();
    };
  }
};

TEST_F(GpuSplitMerge, TilesEqualTheWholeRenderExactly) {
  const scene s = split_scene();
  tiles_equal_the_whole(s, on_gpu(s));
}

TEST_F(GpuSplitMerge, TilesInBandsOfRowsEqualTheWholeRenderExactly) {
  const scene s = split_scene();
  gpu::gpu_render_options small_bands;
  small_bands.band_bytes = 61 * 12 * 5;  // five rows of the image per band
  tiles_equal_the_whole(s, on_gpu(s, small_bands));
}

TEST_F(GpuSplitMerge, SampleHalvesEqualTheWholeRender) {
  const scene s = split_scene();
  // The device sums floats: 3 + 5 samples against 8, each mean rounded to float.
  sample_halves_equal_the_whole(s, on_gpu(s), 1e-5);
}

TEST(SplitMerge, MergeRefusesPiecesThatDoNotMakeOneRender) {
  const scene s = split_scene();
  const camera cam = test::scene_camera(s);
  const int w = cam.image_width(), h = cam.image_height();
  const window_renderer draw = [&](const render_window& win) {
    return framebuffer(win.width, win.height);  // the pixels do not matter here
  };
  const named_partial left = piece(s, cam, {0, 0, 30, h, 0, 4}, draw);
  const named_partial right = piece(s, cam, {30, 0, w - 30, h, 0, 4}, draw);
  EXPECT_NO_THROW(merge_partials({left, right}));
  auto refused = [](const std::vector<named_partial>& parts, const std::string& expect) {
    try {
      merge_partials(parts);
      ADD_FAILURE() << "merged; expected: " << expect;
    } catch (const usage_error& e) {
      EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
    }
  };
  refused({left}, "pixel 30,0 is in none of the parts");
  refused({left, right, piece(s, cam, {29, 0, 2, 2, 3, 5}, draw)}, "hold the same samples");
  refused({left, piece(s, cam, {30, 0, w - 30, h, 0, 2}, draw)},
          "samples 0:2 but pixel 0,0 samples 0:4");
  named_partial other = right;
  other.image.fingerprint = "another scene";
  refused({left, other}, "rendered from a different scene");
  named_partial bigger = right;
  bigger.image.image_width += 1;
  refused({left, bigger}, "image is 62x");
  named_partial older = right;
  older.image.version = "0.0.9";
  refused({left, older}, "rendered by rtvk 0.0.9 with shader s but");
  named_partial other_shader = right;
  other_shader.image.shader = "t";
  refused({left, other_shader}, "--allow-mixed-versions merges them anyway");
  EXPECT_NO_THROW(merge_partials({left, older}, true)) << "allowed when asked";
  // Samples 0:2 and 4:6 of every pixel: same range everywhere, but 2:4 is missing.
  refused({piece(s, cam, {0, 0, w, h, 0, 2}, draw), piece(s, cam, {0, 0, w, h, 4, 6}, draw)},
          "a sample range is missing");
}

TEST(SplitMerge, ExrPiecesKeepTheirHeader) {
  test::temp_dir dir;
  framebuffer fb(3, 2);
  fb.at(2, 1) = color(0.25, 1e-8, 7.5);
  const partial_image p = make_partial(fb, {9,
                                            8,
                                            {4, 5, 3, 2, 10, 20},
                                            {},
                                            2,
                                            "0123456789abcdef",
                                            "book-final",
                                            "front",
                                            17,
                                            "0.1.0",
                                            "fedcba9876543210"});
  write_partial_exr(p, dir.path() / "p.exr");
  const partial_image q = read_partial_exr(dir.path() / "p.exr");
  EXPECT_EQ(q.window, p.window);
  EXPECT_EQ(q.image_width, 9);
  EXPECT_EQ(q.image_height, 8);
  EXPECT_EQ(q.rgb, p.rgb);
  EXPECT_EQ(q.gamma, 2);
  EXPECT_EQ(q.fingerprint, p.fingerprint);
  EXPECT_EQ(q.camera, "front");
  EXPECT_EQ(q.frame, 17);
  EXPECT_EQ(q.version, "0.1.0");
  EXPECT_EQ(q.shader, "fedcba9876543210");
  std::ofstream(dir.path() / "bad.exr") << "not an exr";
  EXPECT_THROW(read_partial_exr(dir.path() / "bad.exr"), image_read_error);
  EXPECT_THROW(read_partial_exr(dir.path() / "none.exr"), image_read_error);
}

}  // namespace
}  // namespace rtvk
