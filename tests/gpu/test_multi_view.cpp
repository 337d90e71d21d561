// Many views of one scene on the GPU: four cameras go out together -- one set-up, one submission
// per batch of samples for all of them -- and each comes back as the CPU reference draws that
// camera.
#include <gtest/gtest.h>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

// book-final through four cameras: the book's, one orbiting, one keyframed, one from above.
// 160 pixels wide: at one sample a path that float rounding sends elsewhere changes its whole
// pixel, and the CPU comparison's PSNR needs enough pixels around it (at 40 wide one such pixel
// could sink it below 40 dB).
scene four_camera_scene() {
  scene s = test::small_scene("book-final", 160, 3);
  s.render.max_depth = 6;
  const camera_pose book = main_camera(s).pose;
  camera_pose above = book;
  above.lookfrom = point3(0, 20, 0.5);
  above.vfov = 40;
  camera_path keyed{camera_motion::keyframes, {}, 0, {{0, book}, {2, above}}};
  s.cameras = {{"book", {camera_motion::fixed, book, 0, {}}},
               {"orbit", {camera_motion::orbit, book, 8, {}}},
               {"swoop", keyed},
               {"above", {camera_motion::fixed, above, 0, {}}}};
  return s;
}

std::vector<camera> cameras_at(const scene& s, double seconds) {
  std::vector<camera> out;
  for (const named_camera& c : s.cameras)
    out.push_back(camera(c.path.at(seconds), s.render.aspect, s.render.width));
  return out;
}

// What lavapipe measured for one view: PSNR (dB) and the share of pixels over 2 levels.
struct measured_view {
  double psnr_db;
  double share;
};

// Each GPU view against the CPU reference through the same camera, scene and settings, within
// what lavapipe measured for it (measured_agreement; book-final's materials scatter).
void expect_each_view_matches_the_cpu(const std::vector<framebuffer>& gpu_views,
                                      const std::vector<camera>& views, const scene& s,
                                      const render_window& win,
                                      const std::vector<measured_view>& measured) {
  ASSERT_EQ(gpu_views.size(), views.size());
  ASSERT_EQ(measured.size(), views.size());
  for (std::size_t k = 0; k < views.size(); ++k) {
    const framebuffer cpu = render_cpu_window(views[k], s, s.render, win);
    const image_difference d =
        compare_images(quantize(gpu_views[k], s.render.gamma), quantize(cpu, s.render.gamma),
                       monte_carlo_agreement.tolerance);
    EXPECT_TRUE(agrees(d, test::measured_agreement(measured[k].psnr_db, measured[k].share,
                                                   cpu.width() * cpu.height())))
        << s.cameras[k].name << ": PSNR " << d.psnr_db << " dB, " << d.pixels_over
        << " pixels more than " << monte_carlo_agreement.tolerance << " levels off (share "
        << d.share_over << "), max " << d.max_abs;
  }
}

using MultiView = test::GpuTest;

// One sample of four views: they go out together, so they take fewer submissions than four
// renders of one view each. (Before the first submission was sized by a short calibration, the
// whole batch was one submission; now the calibration's first dispatch holds 2^14 pixels at the
// first budget, and the four views' 57,600 take three submissions, one view's 14,400 one.)
TEST_F(MultiView, FourCamerasShareSubmissionsAndEachMatchTheCpuReference) {
  scene s = four_camera_scene();
  s.render.spp = 1;
  const std::vector<camera> views = cameras_at(s, 1.0);
  const render_window all = whole_render(views[0].image_width(), views[0].image_height(), 1);
  render_stats together, alone;
  const std::vector<framebuffer> fbs =
      gpu::render_gpu_views(gpu(), views, s, s.render, all, {}, {}, &together);
  gpu::render_gpu_views(gpu(), {views[0]}, s, s.render, all, {}, {}, &alone);
  EXPECT_LT(together.submissions, 4 * alone.submissions);
  expect_each_view_matches_the_cpu(
      fbs, views, s, all,
      {{44.1, 0.00077}, {44.1, 0.00053}, {42.8, 0.00083}, {44.0, 0.00094}});  // measured
  // The four views really differ: a GPU that drew one camera four times would fail above, and
  // this says so directly.
  for (std::size_t k = 1; k < fbs.size(); ++k)
    EXPECT_FALSE(test::same_pixels(fbs[0], fbs[k])) << s.cameras[k].name;
}

TEST_F(MultiView, ManySamplesTakeNoMoreSubmissionsThanOneCamera) {
  const scene s = four_camera_scene();
  const std::vector<camera> views = cameras_at(s, 0.5);
  const render_window all = whole_render(views[0].image_width(), views[0].image_height(), 3);
  render_stats together, alone;
  const auto fbs = gpu::render_gpu_views(gpu(), views, s, s.render, all, {}, {}, &together);
  gpu::render_gpu(gpu(), views[0], s, s.render, {}, {}, &alone);
  expect_each_view_matches_the_cpu(
      fbs, views, s, all,
      {{52.4, 0.0011}, {55.7, 0.0012}, {59.2, 0.00083}, {53.4, 0.0015}});  // measured
  // Submissions grow with time taken, so allow the four-view run one more for its slower batches.
  EXPECT_LE(together.submissions, alone.submissions + 1);
  EXPECT_GE(together.submissions, 1);
}

TEST_F(MultiView, ViewsThatDoNotFitOneBufferGoInGroupsAndStillMatch) {
  const scene s = four_camera_scene();
  const std::vector<camera> views = cameras_at(s, 1.5);
  const int w = views[0].image_width(), h = views[0].image_height();
  gpu::gpu_render_options two_at_a_time;
  two_at_a_time.band_bytes = std::uint64_t(w) * h * 12 * 2;
  gpu::gpu_render_options bands;  // one view at a time, in bands of three rows
  bands.band_bytes = std::uint64_t(w) * 12 * 3;
  const render_window all = whole_render(w, h, s.render.spp);
  const auto reference = gpu::render_gpu_views(gpu(), views, s, s.render, all);
  for (const gpu::gpu_render_options& e : {two_at_a_time, bands}) {
    render_stats st;
    const auto fbs = gpu::render_gpu_views(gpu(), views, s, s.render, all, {}, e, &st);
    for (std::size_t k = 0; k < views.size(); ++k)
      EXPECT_TRUE(test::same_pixels(fbs[k], reference[k])) << s.cameras[k].name;
    EXPECT_GT(st.submissions, 1);
  }
}

}  // namespace
}  // namespace rtvk
