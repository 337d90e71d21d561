// Motion blur on both backends: the camera's shutter draws each sample's instant, and a moving
// sphere is drawn where it is at that instant. Checked against answers worked out by hand, not
// against the renderers themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "render_cpu.h"
#include "render_gpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

class GpuMotion : public test::GpuTest {};

// One flat white sphere of radius 0.5 moving from x = -1 to x = +1 between times 0 and 1, in
// front of a camera at the origin, under a black sky: every sample is 1 where its ray meets the
// sphere at its instant, else 0. Pixel corners only (no jitter), so each pixel has one ray.
scene moving_sphere_scene(int spp) {
  scene s;
  s.name = "moving sphere";
  s.sky = {color(0), color(0)};
  s.materials = {{"white", {material_type::flat, color(1), 0, 1.5}}};
  s.spheres = {sphere(point3(-1, 0, -3), 0.5, 0, point3(1, 0, -3))};
  s.render.width = 48;
  s.render.aspect = 2;
  s.render.spp = spp;
  s.render.max_depth = 2;
  s.render.jitter = false;
  camera_pose& pose = main_camera(s).pose;
  pose.vfov = 40;
  pose.shutter_open = 0;
  pose.shutter_close = 1;
  return s;
}

// The share of the shutter [0, 1] during which ray r meets the sphere (center c0 + t * v,
// radius R): its distance from the ray's line, squared, is a quadratic in t; the share is the
// part of [0, 1] where it is at most R^2.
double share_of_shutter(const ray& r, const point3& c0, const vec3& v, double R) {
  const vec3 d = glm::normalize(r.direction);
  const auto perp = [&](const vec3& x) { return x - glm::dot(x, d) * d; };
  const vec3 w = perp(c0 - r.origin), u = perp(v);
  const double a = glm::dot(u, u), b = 2 * glm::dot(w, u), c = glm::dot(w, w) - R * R;
  const double disc = b * b - 4 * a * c;
  if (a == 0 || disc < 0) return c <= 0 ? 1.0 : 0.0;
  const double t0 = (-b - std::sqrt(disc)) / (2 * a), t1 = (-b + std::sqrt(disc)) / (2 * a);
  return std::max(0.0, std::min(t1, 1.0) - std::max(t0, 0.0));
}

// Each pixel's mean is the share of the shutter its ray sees the sphere, within the binomial
// noise of its samples; and the mean over the image has no bias. With the instant not drawn (every
// sample at the shutter's opening) the sphere sits at x = -1 and most pixels are off by far more.
void expect_shares(const framebuffer& fb, const scene& s, const camera& cam, const char* backend) {
  const int spp = s.render.spp;
  double signed_sum = 0;
  int partial = 0;
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) {
      const int j = fb.height() - 1 - y;  // the lesson counts rows from the bottom
      const ray r = cam.get_ray(pixel_coordinate(x, uint(fb.width())),
                                pixel_coordinate(j, uint(fb.height())));
      const double p = share_of_shutter(r, point3(-1, 0, -3), vec3(2, 0, 0), 0.5);
      const double got = fb.at(x, y).x;
      const double sigma = std::sqrt(p * (1 - p) / spp);
      ASSERT_NEAR(got, p, 5 * sigma + 2e-3) << backend << " pixel " << x << "," << y;
      signed_sum += got - p;
      partial += p > 0.05 && p < 0.95;
    }
  EXPECT_GT(partial, 100) << "the sphere's path covers many pixels partly";
  EXPECT_NEAR(signed_sum / (fb.width() * fb.height()), 0.0, 2e-3) << backend;
}

TEST_F(GpuMotion, EachPixelIsTheShareOfTheShutterItsRaySeesAMovingSphere) {
  const scene s = moving_sphere_scene(1024);
  const camera cam = test::scene_camera(s);
  expect_shares(render_cpu(cam, s, s.render), s, cam, "cpu");
  expect_shares(gpu::render_gpu(gpu(), cam, s, s.render), s, cam, "gpu");
}

// The blurred image is the mean of the instants: 32 images at fixed instants (shutters of no
// length at the middles of 32 equal slices of [0, 1]), averaged, against one image whose
// shutter is open over all of [0, 1], on each backend. The GPU draws the 32 instants as the
// views of one set-up (render_gpu_views: each view bit for bit what it gives alone), not 32
// set-ups: 33 set-ups took 96 s on lavapipe, for renders of 48x24 pixels.
TEST_F(GpuMotion, ABlurredImageIsTheMeanOfImagesAtFixedInstants) {
  constexpr int instants = 32;
  scene blurred = moving_sphere_scene(1024);
  const camera cam = test::scene_camera(blurred);
  const scene still = moving_sphere_scene(1);
  std::vector<camera> stills;
  for (int k = 0; k < instants; ++k) {
    scene at = still;
    camera_pose& pose = main_camera(at).pose;
    pose.shutter_open = pose.shutter_close = (k + 0.5) / instants;
    stills.push_back(test::scene_camera(at));
  }
  for (const bool on_gpu : {false, true}) {
    std::vector<framebuffer> fbs;
    if (on_gpu) {
      fbs = gpu::render_gpu_views(gpu(), stills, still, still.render,
                                  whole_render(cam.image_width(), cam.image_height(), 1));
    } else {
      for (const camera& c : stills) fbs.push_back(render_cpu(c, still, still.render));
    }
    ASSERT_EQ(fbs.size(), std::size_t(instants));
    framebuffer mean(cam.image_width(), cam.image_height());
    for (const framebuffer& fb : fbs)
      for (int y = 0; y < fb.height(); ++y)
        for (int x = 0; x < fb.width(); ++x) mean.at(x, y) += fb.at(x, y) / double(instants);
    const framebuffer blur = on_gpu ? gpu::render_gpu(gpu(), cam, blurred, blurred.render)
                                    : render_cpu(cam, blurred, blurred.render);
    double total = 0, worst = 0;
    for (int y = 0; y < blur.height(); ++y)
      for (int x = 0; x < blur.width(); ++x) {
        const double d = std::abs(blur.at(x, y).x - mean.at(x, y).x);
        total += d;
        worst = std::max(worst, d);
      }
    // Per pixel: the 32 slices misplace an edge by up to one slice (1/32), the 1024 samples
    // add binomial noise (sigma <= 0.016).
    EXPECT_LT(worst, 1.0 / instants + 5 * 0.016) << (on_gpu ? "gpu" : "cpu");
    EXPECT_LT(total / (blur.width() * blur.height()), 0.01) << (on_gpu ? "gpu" : "cpu");
  }
}

// A small sphere that ends a long move near the origin: on the GPU its center at time 1 is
// float(c) + float(t) * float(v), off by far more than a float step of where the host put it,
// and a box of the host's exact positions sliced it flat (148 dark pixels against 176 without
// the BVH). Its box now holds the float error: the BVH image is the search without one's.
TEST_F(GpuMotion, AFarMovingSphereIsNotCulledByItsBoxOnTheGpu) {
  scene s = moving_sphere_scene(1);
  s.spheres = {sphere(point3(-1000000.2, 0, -3), 0.05, 0, point3(0.1, 0, -3))};
  s.motion = {1, 1};
  camera_pose& pose = main_camera(s).pose;
  pose.vfov = 5;
  pose.shutter_open = pose.shutter_close = 1;
  const camera cam = test::scene_camera(s);
  gpu::gpu_render_options linear;
  linear.engine.use_bvh = false;
  const framebuffer with_bvh = gpu::render_gpu(gpu(), cam, s, s.render);
  const framebuffer without = gpu::render_gpu(gpu(), cam, s, s.render, {}, linear);
  int lit = 0;
  for (int y = 0; y < without.height(); ++y)
    for (int x = 0; x < without.width(); ++x) {
      lit += without.at(x, y).x > 0;
      EXPECT_EQ(with_bvh.at(x, y), without.at(x, y)) << "pixel " << x << "," << y;
    }
  EXPECT_GT(lit, 20) << "the sphere is in view";
}

// The second book's bouncing spheres on both backends, within what lavapipe measured
// (measured_agreement): 58.1 dB, 138 pixels (0.24%) over 2 levels of 57,600.
TEST_F(GpuMotion, BouncingSpheresMatchTheCpu) {
  scene s = builtin_scene("bouncing-spheres");
  s.render.width = 320;
  s.render.spp = 8;
  const image_rgb8 cpu = test::cpu_image(s);
  const image_difference d =
      compare_images(test::gpu_image(gpu(), s), cpu, monte_carlo_agreement.tolerance);
  const agreement rule = test::measured_agreement(58.1, 0.0024, cpu.width * cpu.height);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db);
  EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels over 2 levels";
}

// A camera whose shutter samples instants the scene's BVHs do not bound its moving spheres over
// is refused on both backends (a program error: render plans widen the span), never drawn with
// the spheres culled.
TEST_F(GpuMotion, AShutterOutsideTheBoundedSpanIsRefused) {
  scene s = moving_sphere_scene(1);
  s.motion = {0, 1};
  camera_pose& pose = main_camera(s).pose;
  pose.shutter_open = 0.5;
  pose.shutter_close = 1.5;
  const camera cam = test::scene_camera(s);
  EXPECT_THROW(render_cpu(cam, s, s.render), std::invalid_argument);
  EXPECT_THROW(gpu::render_gpu(gpu(), cam, s, s.render), std::invalid_argument);
  s.motion = {0, 2};
  EXPECT_NO_THROW(render_cpu(cam, s, s.render));
}

}  // namespace
}  // namespace rtvk
