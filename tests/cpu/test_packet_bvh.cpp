// The fast mode's own search (host/fast/packet_bvh.h) against the shared kernels' tests run one
// object at a time over every object, the GPU's linear scan: the same hits, bit for bit, and
// exact ties to the later scene index. Compiled with float kernels (tests/CMakeLists.txt), as
// the fast mode compiles them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "packet_bvh.h"
#include "ray_color.h"  // t_min

namespace rtvk::fast {
namespace {

// Spheres (moving ones when `motion`), quads and disks scattered in a box of side 20, in the
// arrays as the GPU packs them (scene indices: spheres, then quads, then disks).
struct objects {
  gpu::scene_arrays a;
  std::vector<quad_geometry> quads;
  std::vector<disk_geometry> disks;
};

real3 random_in(std::mt19937& g, float lo, float hi) {
  std::uniform_real_distribution<float> u(lo, hi);
  return real3(u(g), u(g), u(g));
}

objects scatter_objects(std::uint32_t spheres, std::uint32_t quads, std::uint32_t disks,
                        bool motion, std::mt19937& g) {
  objects o;
  std::uniform_real_distribution<float> size(0.1f, 2.0f);
  std::uint32_t scene_index = 0;
  for (std::uint32_t k = 0; k < spheres; ++k) {
    gpu::gpu_sphere s{};
    s.center = random_in(g, -10, 10), s.radius = size(g), s.scene_index = scene_index++;
    o.a.spheres.push_back(s);
    if (motion) o.a.velocities.push_back(glm::vec4(random_in(g, -1, 1), 0));
  }
  for (std::uint32_t k = 0; k < quads; ++k) {
    quad_geometry q;
    q.Q = random_in(g, -10, 10), q.u = random_in(g, -3, 3), q.v = random_in(g, -3, 3);
    if (k % 2 == 0) {  // in a plane of the axes, as walls are: a box of no thickness
      const int axis = int(k / 2 % 3);
      q.u[axis] = 0, q.v[axis] = 0;
    }
    const real3 n = cross3(q.u, q.v);
    q.normal = unit_vector(n), q.D = dot3(q.normal, q.Q), q.w = divide(n, dot3(n, n));
    o.quads.push_back(q);
    gpu::gpu_quad p{};
    p.scene_index = scene_index++;
    o.a.quads.push_back(p);
  }
  for (std::uint32_t k = 0; k < disks; ++k) {
    disk_geometry d;
    d.center = random_in(g, -10, 10), d.normal = unit_vector(random_in(g, -1, 1));
    d.radius = size(g), d.D = dot3(d.normal, d.center);
    o.disks.push_back(d);
    gpu::gpu_disk p{};
    p.scene_index = scene_index++;
    o.a.disks.push_back(p);
  }
  return o;
}

packet_bvh tree_of(const objects& o) {
  return packet_bvh(o.a, std::uint32_t(o.a.spheres.size()), o.quads, std::uint32_t(o.quads.size()),
                    o.disks, std::uint32_t(o.disks.size()), 0.0f, 1.0f);
}

// The GPU's linear scan: every object's kernel test, the nearest kept, ties to the later one.
bool scan(const objects& o, const ray& r, real t_min, real t_max, packet_bvh::found& f) {
  bool hit = false;
  std::uint32_t best_key = 0;
  const auto offer = [&](std::uint32_t kind, std::uint32_t k, std::uint32_t key, real t) {
    if (hit && !(t < f.t || (t == f.t && key > best_key))) return;
    hit = true, f = {kind, k, t}, best_key = key, t_max = t;
  };
  real t;
  for (std::uint32_t k = 0; k < o.a.spheres.size(); ++k) {
    const gpu::gpu_sphere& s = o.a.spheres[k];
    const real3 c = o.a.velocities.empty()
                        ? real3(s.center)
                        : moved_center(s.center, real3(o.a.velocities[k]), r.time);
    if (hit_sphere(c, s.radius, r, t_min, t_max, t))
      offer(packet_bvh::sphere_kind, k, s.scene_index, t);
  }
  for (std::uint32_t k = 0; k < o.quads.size(); ++k) {
    real2 uv;
    if (hit_quad(o.quads[k], r, t_min, t_max, t, uv))
      offer(packet_bvh::quad_kind, k, o.a.quads[k].scene_index, t);
  }
  for (std::uint32_t k = 0; k < o.disks.size(); ++k)
    if (hit_disk(o.disks[k], r, t_min, t_max, t))
      offer(packet_bvh::disk_kind, k, o.a.disks[k].scene_index, t);
  return hit;
}

// Rays from inside and outside the objects' box, toward random points, at random instants;
// some start far away (the slab test's margin), some run along an axis (zero components).
ray random_ray(std::mt19937& g, int k) {
  const real3 from = random_in(g, k % 7 == 0 ? -1e4f : -15, k % 7 == 0 ? 1e4f : 15);
  real3 d = random_in(g, -10, 10) - from;
  if (k % 11 == 0) d = real3(0, 0, d.z);
  std::uniform_real_distribution<float> time(0, 1);
  return ray(from, d, time(g));
}

void expect_scan(const objects& o, int rays, std::mt19937& g) {
  const packet_bvh tree = tree_of(o);
  int hits = 0;
  for (int k = 0; k < rays; ++k) {
    const ray r = random_ray(g, k);
    const real t_max = k % 3 == 0 ? std::numeric_limits<real>::max() : real(5 + k % 17);
    packet_bvh::found want, got;
    const bool expected = scan(o, r, t_min, t_max, want);
    ASSERT_EQ(tree.hit(r, t_min, t_max, got), expected) << "ray " << k;
    ASSERT_EQ(tree.blocked(r, t_min, t_max), expected) << "ray " << k;
    if (!expected) continue;
    ++hits;
    ASSERT_EQ(got.kind, want.kind) << "ray " << k;
    ASSERT_EQ(got.index, want.index) << "ray " << k;
    ASSERT_EQ(std::bit_cast<std::uint32_t>(got.t), std::bit_cast<std::uint32_t>(want.t))
        << "ray " << k << ": " << got.t << " against " << want.t;
  }
  // Enough of both outcomes that each was tested.
  EXPECT_GE(hits, 3);
  EXPECT_GE(rays - hits, 3);
}

TEST(PacketBvh, FindsTheScansHitsBitForBit) {
  std::mt19937 g(47);
  expect_scan(scatter_objects(300, 200, 100, false, g), 20000, g);
}

TEST(PacketBvh, MovingSpheres) {
  std::mt19937 g(48);
  expect_scan(scatter_objects(400, 0, 0, true, g), 10000, g);
}

TEST(PacketBvh, FewObjectsOfEachKind) {
  std::mt19937 g(49);
  for (std::uint32_t n = 1; n <= 6; ++n) {
    expect_scan(scatter_objects(n, n % 3, n % 2, n % 2 == 0, g), 3000, g);
    expect_scan(scatter_objects(n, 0, 0, false, g), 3000, g);  // n <= 4: a root that is a leaf
  }
}

// Coincident copies of spheres, quads and disks (each object four times over), their scene
// indices shuffled across kinds: ties met in different leaves and between kinds go to the later
// scene index, as the scan gives them.
TEST(PacketBvh, TiesAcrossLeavesAndKinds) {
  std::mt19937 g(50);
  const objects unique = scatter_objects(30, 30, 30, false, g);
  objects o;
  for (int copy = 0; copy < 4; ++copy) {
    o.a.spheres.insert(o.a.spheres.end(), unique.a.spheres.begin(), unique.a.spheres.end());
    o.a.quads.insert(o.a.quads.end(), unique.a.quads.begin(), unique.a.quads.end());
    o.quads.insert(o.quads.end(), unique.quads.begin(), unique.quads.end());
    o.a.disks.insert(o.a.disks.end(), unique.a.disks.begin(), unique.a.disks.end());
    o.disks.insert(o.disks.end(), unique.disks.begin(), unique.disks.end());
  }
  std::vector<std::uint32_t> keys(o.a.spheres.size() + o.a.quads.size() + o.a.disks.size());
  for (std::uint32_t k = 0; k < keys.size(); ++k) keys[k] = k;
  std::shuffle(keys.begin(), keys.end(), g);
  std::size_t next = 0;
  for (gpu::gpu_sphere& s : o.a.spheres) s.scene_index = keys[next++];
  for (gpu::gpu_quad& q : o.a.quads) q.scene_index = keys[next++];
  for (gpu::gpu_disk& d : o.a.disks) d.scene_index = keys[next++];
  expect_scan(o, 5000, g);
}

// Spheres that grow geometrically in size and spacing, over 16 orders of magnitude: the surface
// area heuristic would peel a few off per level, deeper than the traversal's stack; the builder
// turns to median splits in time, and the search still finds the scan's hits.
TEST(PacketBvh, GeometricScenesStayWithinTheStack) {
  objects o;
  for (std::uint32_t k = 0; k < 15000; ++k) {
    const double scale = std::pow(1.00245, k), angle = 0.05 * k;
    gpu::gpu_sphere s{};
    s.center = real3(float(scale * std::cos(angle)), float(scale * std::sin(angle)),
                     float(0.2 * scale * std::sin(3 * angle)));
    s.radius = float(0.03 * scale), s.scene_index = k;
    o.a.spheres.push_back(s);
  }
  const packet_bvh tree = tree_of(o);
  EXPECT_LE(tree.levels(), packet_bvh::max_levels);
  std::mt19937 g(51);
  std::uniform_int_distribution<std::uint32_t> pick(0, 14999);
  for (int k = 0; k < 200; ++k) {  // rays from the origin's side toward random spheres
    const gpu::gpu_sphere& s = o.a.spheres[pick(g)];
    const ray r(real3(0.1f, 0.2f, 0.3f), real3(s.center) - real3(0.1f, 0.2f, 0.3f));
    packet_bvh::found want, got;
    const bool expected = scan(o, r, t_min, 2, want);
    ASSERT_EQ(tree.hit(r, t_min, 2, got), expected) << "ray " << k;
    if (expected) {
      EXPECT_EQ(got.index, want.index) << "ray " << k;
    }
  }
}

// Two quads in one plane, overlapping: every hit on the overlap is an exact tie, which goes to
// the later quad in the scene, as on the GPU (world.glsl), whatever the tree's order.
TEST(PacketBvh, ExactTiesGoToTheLaterObject) {
  objects o;
  for (std::uint32_t k = 0; k < 2; ++k) {
    quad_geometry q;
    q.Q = real3(real(-1) + real(k), -1, 0), q.u = real3(2, 0, 0), q.v = real3(0, 2, 0);
    q.normal = real3(0, 0, 1), q.D = 0, q.w = real3(0, 0, 0.25f);
    o.quads.push_back(q);
    gpu::gpu_quad p{};
    p.scene_index = k;
    o.a.quads.push_back(p);
  }
  for (std::uint32_t order = 0; order < 2; ++order) {
    if (order == 1) {  // the later one first in the arrays
      std::swap(o.quads[0], o.quads[1]);
      std::swap(o.a.quads[0], o.a.quads[1]);
    }
    const packet_bvh tree = tree_of(o);
    packet_bvh::found f;
    ASSERT_TRUE(tree.hit(ray(real3(0.5f, 0, 5), real3(0, 0, -1)), t_min, 100, f));
    EXPECT_EQ(o.a.quads[f.index].scene_index, 1u) << "order " << order;
    ASSERT_TRUE(tree.hit(ray(real3(-0.5f, 0, 5), real3(0, 0, -1)), t_min, 100, f));
    EXPECT_EQ(o.a.quads[f.index].scene_index, 0u) << "order " << order;
  }
}

TEST(PacketBvh, NothingToHit) {
  const objects o;
  const packet_bvh tree = tree_of(o);
  packet_bvh::found f;
  EXPECT_TRUE(tree.empty());
  EXPECT_FALSE(tree.hit(ray(real3(0), real3(0, 0, 1)), t_min, 100, f));
  EXPECT_FALSE(tree.blocked(ray(real3(0), real3(0, 0, 1)), t_min, 100));
}

}  // namespace
}  // namespace rtvk::fast
