// The BVH must find exactly the hits the linear scan finds, for any ray: its box tests run in
// float, so they have to be conservative wherever the ray starts, including far from the boxes.
#include <gtest/gtest.h>

#include <cstring>
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

// Spheres that binned SAH stacks deep: a logarithmic spiral whose spheres grow geometrically,
// each 1.01 times farther out and larger than the last, 4000 of them over a range of 10^17 (a
// scene file allows 10^18). The largest spheres dominate every node's bins, so SAH alone peels
// them off a few at a time and builds 53 levels; the builder must stay within bvh::max_depth all
// the same. Every 101st sphere is repeated at the end with material 1: on those exact ties the
// repeat must win.
std::vector<sphere> growing_spiral(int n) {
  std::vector<sphere> out;
  for (int i = 0; i < n; ++i) {
    const double scale = std::pow(1.01, i), angle = 0.05 * i;
    out.emplace_back(scale * point3(std::cos(angle), std::sin(angle), 0.2 * std::sin(3 * angle)),
                     0.03 * scale, 0);
  }
  for (int i = 0; i < n; i += 101)
    out.emplace_back(out[std::size_t(i)].center, out[std::size_t(i)].radius, 1);
  return out;
}

// Interior levels on the longest path from node `at`, read from the nodes themselves; checks on
// the way that every leaf holds 1 to max_leaf spheres and counts the slots the leaves cover.
int walk_depth(const bvh& tree, std::uint32_t at, std::vector<int>& slot_uses) {
  const bvh_node& n = tree.nodes()[at];
  int below = 0;
  for (int c = 0; c < 2; ++c) {
    if (n.count[c] == 0) {
      EXPECT_GT(n.first[c], at) << "children follow their parents";
      if (n.first[c] <= at || n.first[c] >= tree.nodes().size()) return 1 << 20;
      below = std::max(below, walk_depth(tree, n.first[c], slot_uses));
      continue;
    }
    EXPECT_LE(n.count[c], std::uint32_t(bvh::max_leaf));
    for (std::uint32_t k = n.first[c]; k < n.first[c] + n.count[c]; ++k) ++slot_uses.at(k);
  }
  return 1 + below;
}

TEST(BvhDepth, SpheresThatSahChainsStayWithinTheStackAndHitLikeTheLinearScan) {
  const std::vector<sphere> spheres = growing_spiral(4000);
  const bvh_world tree(spheres);
  std::vector<int> slot_uses(spheres.size());
  const bvh binary(spheres);  // the tree bvh_world collapsed
  const int depth = walk_depth(binary, 0, slot_uses);
  EXPECT_EQ(depth, binary.depth());
  ASSERT_LE(depth, bvh::max_depth) << "deeper than the traversal stack holds";
  EXPECT_EQ(std::count(slot_uses.begin(), slot_uses.end(), 1), std::ptrdiff_t(spheres.size()))
      << "every slot in exactly one leaf";
  std::vector<std::uint32_t> order = binary.order();
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], i) << "a permutation";

  hittable_list list;
  for (const sphere& s : spheres) list.add(std::make_shared<hittable_sphere>(s));
  std::mt19937_64 rng(4000);
  std::uniform_int_distribution<std::size_t> pick(0, spheres.size() - 1);
  std::uniform_real_distribution<double> graze(0.9, 1.05), distance(0, 4), unit(0, 1);
  int hits = 0, repeats_won = 0, mismatches = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Aimed at a sphere's silhouette, from 1 to 10,000 of its radii away, or (one ray in four)
    // from near the spiral's center outwards, through many of its turns.
    const sphere& target = spheres[pick(rng)];
    const vec3 d = random_unit(rng);
    const vec3 across = glm::normalize(glm::cross(d, random_unit(rng)));
    const point3 aim = target.center + target.radius * graze(rng) * across;
    const point3 origin = unit(rng) < 0.25
                              ? point3(0.5 * random_unit(rng))
                              : aim - target.radius * std::pow(10.0, distance(rng)) * d;
    const ray r(origin, aim - origin);
    hit_record from_tree, from_list;
    const bool in_tree = tree.hit(r, 0.001, std::numeric_limits<double>::infinity(), from_tree);
    const bool in_list = list.hit(r, 0.001, std::numeric_limits<double>::infinity(), from_list);
    hits += in_list;
    repeats_won += in_list && from_list.material == 1;
    if (in_tree != in_list ||
        (in_list && (from_tree.t != from_list.t || from_tree.material != from_list.material ||
                     from_tree.p != from_list.p))) {
      if (++mismatches <= 5)
        ADD_FAILURE() << "trial " << trial << ": the list " << (in_list ? "hits" : "misses")
                      << " at " << from_list.t << " (material " << from_list.material
                      << "), the BVH " << (in_tree ? "hits" : "misses") << " at " << from_tree.t
                      << " (material " << from_tree.material << ")";
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(hits, 5000) << "the rays must hit often for the test to mean something";
  EXPECT_LT(hits, 19500) << "and miss sometimes";
  EXPECT_GT(repeats_won, 10) << "and some hits must be exact ties";
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

// The build runs subtrees and large ranges' binning as parallel tasks; node positions follow
// from the ranges alone, so the tree must be the same bytes however many threads build it. And
// it must be a tree: children after their parents, every sphere in exactly one leaf, each leaf's
// box around its sphere.
TEST(BvhBuild, TheTreeIsTheSameOnOneThreadAndOnManyAndHoldsEverySphere) {
  std::mt19937_64 rng(1000000);
  const std::vector<sphere> spheres = scattered_spheres(rng, 150000);  // past every threshold
  const bvh one(spheres, 1), many(spheres, 4);
  ASSERT_EQ(one.nodes().size(), spheres.size() - 1);
  ASSERT_EQ(many.nodes().size(), one.nodes().size());
  EXPECT_EQ(
      std::memcmp(one.nodes().data(), many.nodes().data(), one.nodes().size() * sizeof(bvh_node)),
      0);
  EXPECT_EQ(one.order(), many.order());
  EXPECT_EQ(one.depth(), many.depth());
  std::vector<int> slot_uses(spheres.size());
  EXPECT_EQ(walk_depth(many, 0, slot_uses), many.depth());
  EXPECT_EQ(std::count(slot_uses.begin(), slot_uses.end(), 1), std::ptrdiff_t(spheres.size()));
  int outside = 0;
  for (const bvh_node& n : many.nodes())
    for (int c = 0; c < 2; ++c) {
      if (n.count[c] == 0) continue;
      const sphere& s = spheres[many.order()[n.first[c]]];
      const glm::vec4* const axes[3] = {&n.x, &n.y, &n.z};
      for (int k = 0; k < 3; ++k)
        outside += !(double((*axes[k])[c]) <= s.center[k] - s.radius &&
                     s.center[k] + s.radius <= double((*axes[k])[c + 2]));
    }
  EXPECT_EQ(outside, 0) << "leaf boxes that do not hold their sphere";
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

// The same spiral on the GPU, through its BVH and through the linear scan: seen from above and
// from its center (spheres of every size), with the repeats in a scattering material so that a
// tie won by the wrong sphere shows. (Not from much farther away: the GPU's float camera rays
// and sphere tests do not reach that far.)
TEST_F(GpuBvh, SpheresThatSahChainsLookTheSameThroughTheBvhOnTheGpu) {
  scene s = builtin_scene("seed");
  s.spheres = growing_spiral(4000);
  s.materials = {{"normal", material{}},
                 {"red", material{material_type::lambertian, color(0.9, 0.2, 0.1), 0, 1.5}}};
  s.render.width = 64;
  s.render.aspect = 1;
  s.render.spp = 1;
  s.render.max_depth = 4;  // the linear scan's loop budget: 4 x 4040 sphere tests
  for (const camera_pose& pose :
       {camera_pose{point3(0, 0, 2000), point3(0, 0, 0), vec3(0, 1, 0), 60, 0, 1},
        camera_pose{point3(0, 0, 0.3), point3(1, 0.2, 0), vec3(0, 0, 1), 100, 0, 1}}) {
    s.cameras[0].path = camera_path{};
    s.cameras[0].path.pose = pose;
    const camera cam = test::scene_camera(s);
    auto draw = [&](bool use_bvh) {
      return quantize(
          gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = {.use_bvh = use_bvh}}), 1);
    };
    const image_rgb8 linear = draw(false);
    EXPECT_TRUE(has_spheres(linear)) << pose.lookfrom.z;
    EXPECT_EQ(draw(true).rgb, linear.rgb) << "from " << pose.lookfrom.z;
  }
}

}  // namespace
}  // namespace rtvk
