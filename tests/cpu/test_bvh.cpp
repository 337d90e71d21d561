// The BVH must find exactly the hits the linear scan finds, for any ray: its box tests run in
// float, so they have to be conservative wherever the ray starts, including far from the boxes.
#include <gtest/gtest.h>

#include <random>

#include "bvh_world.h"
#include "gpu_fixture.h"
#include "hittable_list.h"
#include "hittable_sphere.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

// Small spheres, of sizes from a hundredth to one, scattered through a 20-unit cube.
std::vector<sphere> scattered_spheres(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> pos(-10, 10), radius(-2, 0);
  std::vector<sphere> out;
  for (int i = 0; i < n; ++i)
    out.emplace_back(point3(pos(rng), pos(rng), pos(rng)), std::pow(10.0, radius(rng)), 0);
  return out;
}

vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(vec3(g(rng), g(rng), g(rng)));
}

TEST(BvhProperty, FarAwayRaysFindTheHitsOfTheLinearScan) {
  std::mt19937_64 rng(20261123);
  const std::vector<sphere> spheres = scattered_spheres(rng, 300);
  const bvh_world tree(spheres);
  hittable_list list;
  for (const sphere& s : spheres) list.add(std::make_shared<hittable_sphere>(s));
  std::uniform_int_distribution<std::size_t> pick(0, spheres.size() - 1);
  std::uniform_real_distribution<double> graze(0.98, 1.02), exponent(2, 7);
  int hits = 0, mismatches = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Aimed at a sphere's silhouette, from 100 to 10,000,000 units away in any direction: the
    // rays that a box test rounding the origin to float, or padding only by the box's own size,
    // gets wrong.
    const sphere& target = spheres[pick(rng)];
    const vec3 d = random_unit(rng);
    const vec3 across = glm::normalize(glm::cross(d, random_unit(rng)));
    const point3 aim = target.center + target.radius * graze(rng) * across;
    const point3 origin = aim - std::pow(10.0, exponent(rng)) * d;
    const ray r(origin, aim - origin);
    hit_record from_tree, from_list;
    const bool in_tree = tree.hit(r, 0.001, std::numeric_limits<double>::infinity(), from_tree);
    const bool in_list = list.hit(r, 0.001, std::numeric_limits<double>::infinity(), from_list);
    hits += in_list;
    if (in_tree != in_list || (in_list && from_tree.t != from_list.t)) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "trial " << trial << ": origin " << origin.x << "," << origin.y << ","
                      << origin.z << ": the list " << (in_list ? "hits" : "misses") << ", the BVH "
                      << (in_tree ? "hits" : "misses");
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hits, 5000) << "the rays must hit often for the test to mean something";
  EXPECT_LT(hits, 15000) << "and miss often: they graze";
}

// The same on both backends as images: a camera far away (from ten thousand to ten million
// units), zoomed in on a field of small spheres, sees the same picture through the BVH and
// through the linear scan.
const double far_distances[] = {1e4, 1e5, 1e6, 1e7};

scene far_camera_scene(double distance) {
  scene s = builtin_scene("spheres:300");
  s.render.width = 96;
  s.render.aspect = 1;
  s.render.spp = 1;
  s.render.jitter = false;
  const point3 from = distance * glm::normalize(vec3(1, 0.4, 1));
  // A view about 12 units tall at the look-at point: the field of spheres fills it.
  const double vfov = 2 * std::atan(6 / distance) * 180 / 3.14159265358979323846;
  s.cameras[0].path = camera_path{};
  s.cameras[0].path.pose = {from, point3(0, 0, 0), vec3(0, 1, 0), vfov, 0, 1};
  for (named_material& m : s.materials) m.m = material{};  // normal shading: no scattering
  return s;
}

bool has_spheres(const image_rgb8& img) {
  return std::count(img.rgb.begin(), img.rgb.end(), img.rgb[0]) != std::ptrdiff_t(img.rgb.size());
}

TEST(BvhProperty, ACameraFarAwaySeesTheSameThroughTheBvhOnTheCpu) {
  for (const double distance : far_distances) {
    const scene s = far_camera_scene(distance);
    const camera cam = test::scene_camera(s);
    const image_rgb8 linear = quantize(render_cpu(cam, s, s.render, {}, {.use_bvh = false}), 1);
    EXPECT_TRUE(has_spheres(linear)) << distance;
    EXPECT_EQ(quantize(render_cpu(cam, s, s.render, {}, {.use_bvh = true}), 1).rgb, linear.rgb)
        << "from " << distance;
  }
}

class GpuBvh : public test::GpuTest {};

TEST_F(GpuBvh, ACameraFarAwaySeesTheSameThroughTheBvhOnTheGpu) {
  for (const double distance : far_distances) {
    const scene s = far_camera_scene(distance);
    const camera cam = test::scene_camera(s);
    auto draw = [&](bool use_bvh) {
      return quantize(
          gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = {.use_bvh = use_bvh}}), 1);
    };
    const image_rgb8 linear = draw(false);
    EXPECT_TRUE(has_spheres(linear)) << distance;
    EXPECT_EQ(draw(true).rgb, linear.rgb) << "from " << distance;
  }
}

}  // namespace
}  // namespace rtvk
