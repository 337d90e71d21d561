// The ground truth beside the image (--aov): on a scene whose every pixel can be worked out by
// hand -- a wall, a ball and a box seen by a calibrated pinhole -- both backends give the
// distances, depths, normals, albedos and ids the geometry says, and the same ids at every pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "aov_output.h"
#include "aov_pass.h"
#include "camera.h"
#include "gpu_engine.h"
#include "gpu_fixture.h"
#include "object_ids.h"
#include "render_aov.h"
#include "scene.h"

namespace rtvk {
namespace {

constexpr int width = 160, height = 120;
constexpr double fx = 100, cx = 79.5, cy = 59.5;
const point3 ball_center(2, 1, -6);
constexpr double ball_radius = 1.5;
const point3 box_lo(-4, -3, -8), box_hi(-1.5, -0.5, -7);

scene known_scene() {
  scene s;
  s.materials = {{"wall", {material_type::lambertian, {0.25, 0.5, 0.75}}},
                 {"ball", {material_type::metal, {0.9, 0.8, 0.1}}},
                 {"box", {material_type::dielectric}}};
  s.spheres.push_back(sphere(ball_center, ball_radius, 1));
  s.quads.push_back({point3(-40, -40, -10), vec3(80, 0, 0), vec3(0, 80, 0), 0});
  add_box(s, box_lo, box_hi, 2);
  camera_pose& p = s.cameras[0].path.pose;
  p.lookfrom = point3(0, 0, 0);
  p.lookat = point3(0, 0, -1);
  p.projection = projection::opencv;
  p.intrinsics = {width, height, fx, fx, cx, cy, {}, 0};
  return s;
}

// What the ray through pixel (x, y) meets first, worked out here: the world direction of the
// OpenCV pixel (x right, y down; the camera looks down -z with +y up).
struct expected_hit {
  int object;         // 1 ball, 2 wall, 3 box (spheres, then quads: the wall, then the box)
  double t;           // along the unit direction
  vec3 normal;        // facing the camera
  bool clear = true;  // not within a hair of another surface's edge
};

expected_hit expect(int x, int y) {
  const vec3 d = glm::normalize(vec3((x - cx) / fx, -(y - cy) / fx, -1));
  expected_hit best{2, 10 / -d.z, vec3(0, 0, 1)};
  // The ball: |t d - c|^2 = r^2.
  const double b = glm::dot(d, ball_center),
               c = glm::dot(ball_center, ball_center) - ball_radius * ball_radius;
  const double disc = b * b - c;
  if (disc > 0 && b - std::sqrt(disc) < best.t) {
    const double t = b - std::sqrt(disc);
    best = {1, t, glm::normalize(t * d - ball_center)};
  }
  if (std::abs(disc) < 1e-3) best.clear = false;
  // The box: slabs.
  double t0 = 0, t1 = 1e30, entries[3];
  int axis = 0;
  for (int k = 0; k < 3; ++k) {
    double a = box_lo[k] / d[k], z = box_hi[k] / d[k];
    if (a > z) std::swap(a, z);
    entries[k] = a;
    if (a > t0) t0 = a, axis = k;
    t1 = std::min(t1, z);
  }
  if (std::abs(t1 - t0) < 1e-3) best.clear = false;  // grazing the box's outline
  for (int k = 0; k < 3; ++k)  // on an edge between two faces: either normal is right
    if (k != axis && t0 < t1 && std::abs(entries[k] - t0) < 1e-3) best.clear = false;
  if (t0 < t1 && t0 < best.t) {
    vec3 n(0);
    n[axis] = d[axis] > 0 ? -1 : 1;
    best = {3, t0, n, best.clear};
  }
  return best;
}

class GpuAov : public test::GpuTest {};

// rtvk render's AOVs go through the render's own scene and tree (gpu_engine::device_scene), one
// pass for every image of the run: each view's ground truth must be what a pass over a scene of
// its own finds, bit for bit, the second view's too (its camera written again, its rows read
// back again; a window of another size grows the pass's buffer).
TEST_F(GpuAov, OnePassOverTheRendersSceneServesEveryView) {
  const scene s = known_scene();
  gpu::gpu_engine engine(gpu(), s);
  ASSERT_TRUE(engine.scene_has_bvh());
  gpu::aov_pass pass(gpu(), engine.device_scene(), engine.scene_has_bvh());
  camera_pose turned = s.cameras[0].path.pose;
  turned.lookfrom = turned.lookfrom + vec3(0.4, 0.3, 0);
  for (const auto& [pose, w] :
       {std::pair{s.cameras[0].path.pose, width}, std::pair{turned, 2 * width}}) {
    const camera cam(pose, double(width) / height, w);
    const render_window win = whole_render(cam.image_width(), cam.image_height(), 1);
    const std::vector<gpu::gpu_aov> shared = pass.run(cam, win);
    const std::vector<gpu::gpu_aov> own = gpu::run_aov_pass(gpu(), s, true, cam, win);
    ASSERT_EQ(shared.size(), own.size());
    EXPECT_EQ(std::memcmp(shared.data(), own.data(), own.size() * sizeof(gpu::gpu_aov)), 0)
        << "view " << w;
  }
}

TEST_F(GpuAov, AKnownScenesGroundTruthIsExactOnBothBackends) {
  const scene s = known_scene();
  const camera cam(s.cameras[0].path.pose, double(width) / height, width);
  ASSERT_EQ(cam.image_height(), height);
  const render_window win = whole_render(width, height, 1);
  const object_ids ids(s);
  EXPECT_EQ(ids.count(), 3u);  // the box's six quads are one object
  const std::vector<gpu::gpu_aov> cpu = render_aov_cpu(cam, s, win);
  const std::vector<gpu::gpu_aov> dev = gpu::run_aov_pass(gpu(), s, true, cam, win);
  const std::vector<gpu::gpu_aov> scan = gpu::run_aov_pass(gpu(), s, false, cam, win);
  const aov_image a = aov_from(
      dev, ids, aov_depth | aov_normal | aov_albedo | aov_object_id | aov_material_id, win);
  const aov_image b = aov_from(cpu, ids, a.which, win);
  const aov_image c = aov_from(scan, ids, a.which, win);
  int checked = 0, seen[4] = {};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t k = std::size_t(y) * width + std::size_t(x);
      // The same ids at every pixel, on both backends and both searches.
      ASSERT_EQ(a.object_id[k], b.object_id[k]) << "pixel " << x << ", " << y;
      ASSERT_EQ(c.object_id[k], b.object_id[k]) << "pixel " << x << ", " << y;
      ASSERT_EQ(a.material_id[k], b.material_id[k]) << "pixel " << x << ", " << y;
      const expected_hit e = expect(x, y);
      if (!e.clear) continue;
      ++checked;
      ++seen[e.object];
      for (const aov_image* got : {&a, &b}) {
        ASSERT_EQ(got->object_id[k], std::uint32_t(e.object)) << "pixel " << x << ", " << y;
        ASSERT_EQ(got->material_id[k], std::uint32_t(e.object == 1 ? 2 : e.object == 2 ? 1 : 3));
        const vec3 d = glm::normalize(vec3((x - cx) / fx, -(y - cy) / fx, -1));
        EXPECT_NEAR(got->distance[k], e.t, 2e-6 * e.t) << "pixel " << x << ", " << y;
        EXPECT_NEAR(got->depth[k], -e.t * d.z, 2e-6 * e.t) << "pixel " << x << ", " << y;
        for (int ch = 0; ch < 3; ++ch)
          EXPECT_NEAR(got->normal[3 * k + std::size_t(ch)], e.normal[ch], 1e-4);
        const color albedo = e.object == 1   ? color(0.9, 0.8, 0.1)
                             : e.object == 2 ? color(0.25, 0.5, 0.75)
                                             : color(1, 1, 1);  // glass: white
        for (int ch = 0; ch < 3; ++ch)
          EXPECT_FLOAT_EQ(got->albedo[3 * k + std::size_t(ch)], float(albedo[ch]));
      }
    }
  EXPECT_GT(checked, width * height * 9 / 10);
  EXPECT_GT(seen[1], 500);  // the ball, the wall and the box are all in view
  EXPECT_GT(seen[2], 5000);
  EXPECT_GT(seen[3], 500);
}

TEST_F(GpuAov, PixelsOutsideAFisheyesFieldSeeNothing) {
  scene s = known_scene();
  camera_pose& p = s.cameras[0].path.pose;
  p.projection = projection::opencv_fisheye;
  p.intrinsics = {width, height, 30, 30, cx, cy, {}, 0};  // a circle of about 47 pixels
  const camera cam(p, double(width) / height, width);
  const render_window win = whole_render(width, height, 1);
  const std::vector<gpu::gpu_aov> dev = gpu::run_aov_pass(gpu(), s, true, cam, win);
  const std::vector<gpu::gpu_aov> cpu = render_aov_cpu(cam, s, win);
  int outside = 0;
  for (std::size_t k = 0; k < dev.size(); ++k) {
    EXPECT_EQ(dev[k].hit, cpu[k].hit);
    if (!cpu[k].hit) {
      ++outside;
      EXPECT_TRUE(std::isinf(dev[k].distance) && std::isinf(cpu[k].depth));
    }
  }
  EXPECT_GT(outside, 1000);  // the corners, beyond 90 degrees from the axis
}

}  // namespace
}  // namespace rtvk
