#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "bvh_node.h"
#include "bvh_types.h"
#include "shape_lists.h"

namespace rtvk {

// The kinds of shape, numbered as their leaf codes (RTVK_LEAF_* >> RTVK_LEAF_KIND_SHIFT) and in
// scene-index order: the arrays a traversal reads are one per kind, indexed by these.
enum shape_kind : std::size_t { shape_sphere, shape_quad, shape_triangle, shape_disk };
inline constexpr std::size_t shape_kinds = RTVK_SHAPE_KINDS;
static_assert(shape_disk + 1 == shape_kinds, "a kind without its place in shape_kind");

// A count per shape kind.
using kind_counts = std::array<std::uint32_t, shape_kinds>;

// The leaf code of kind k.
constexpr std::uint32_t leaf_code(std::size_t k) {
  return std::uint32_t(k) << RTVK_LEAF_KIND_SHIFT;
}

// The objects a BVH is built over, numbered as one list: spheres, then quads, triangles and
// disks (scene::spheres, quads, triangles, disks; an object's number is its scene index).
struct primitive_spans {
  std::span<const sphere> spheres;
  std::span<const quad> quads;
  std::span<const triangle> triangles;
  std::span<const disk> disks = {};
  // After the shapes: anything else by its box alone, corners lo and hi (instances).
  std::span<const std::array<point3, 2>> boxes = {};
  // How many of each kind, in shape_kind order.
  std::array<std::size_t, shape_kinds> counts() const {
    return {spheres.size(), quads.size(), triangles.size(), disks.size()};
  }
  std::size_t shapes() const {
    return spheres.size() + quads.size() + triangles.size() + disks.size();
  }
  std::size_t size() const { return shapes() + boxes.size(); }
};

// The spans of a scene's or a group's lists.
inline primitive_spans spans_of(const shape_lists& l) {
  return primitive_spans{l.spheres, l.quads, l.triangles, l.disks};
}

// A bounding volume hierarchy over objects (spheres, quads, triangles), built with binned SAH and
// flattened depth first into one array of interior nodes (bvh_node.h), each holding both
// children's boxes and references; leaves live in their parents. Both backends traverse the same
// tree collapsed four wide (wide_bvh.h: cpu/bvh_world.h, shaders/world.glsl). Leaves refer to
// sphere slots, the spheres in leaf order; order() gives each slot's index in the scene, so hits
// can be kept identical to a linear scan.
class bvh {
 public:
  // Built on `threads` threads (0: one per core); the tree does not depend on how many. A moving
  // sphere's box holds it over the whole of `motion` (it moves in a straight line, so its boxes
  // at the two ends bound it in between). Throws std::length_error for more spheres than a tree
  // of max_depth levels holds.
  explicit bvh(std::span<const sphere> spheres, int threads = 0, time_span motion = {});
  // Over objects of every kind; order() then gives scene indices in primitive_spans' numbering.
  explicit bvh(const primitive_spans& objects, int threads = 0, time_span motion = {});

  // Interior nodes, node 0 the root; none when there are no spheres. One sphere makes a root
  // whose two children are the same leaf.
  const std::vector<bvh_node>& nodes() const { return nodes_; }
  // Leaf slot -> index into the scene's spheres; every sphere has exactly one slot.
  const std::vector<std::uint32_t>& order() const { return order_; }
  // Interior levels on the longest path from the root (the root alone: 1; no spheres: 0).
  int depth() const { return depth_; }

  // Most spheres in one leaf. Every leaf holds exactly one: the shader's traversal stack
  // (shaders/world.glsl) marks a remembered child as a leaf by one bit and takes it to hold one
  // sphere; a larger max_leaf needs room there for the count.
  static constexpr int max_leaf = RTVK_BVH_LEAF;
  static_assert(max_leaf == 1, "world.glsl's stack holds no leaf sizes");
  // Most interior levels: a traversal remembers at most one child per interior level on its
  // path, so RTVK_BVH_STACK stack entries always suffice. SAH splits that would need more levels
  // below them than are left give way to median splits, which fit up to max_leaf * 2^max_depth
  // spheres.
  static constexpr int max_depth = RTVK_BVH_STACK;

 private:
  std::vector<bvh_node> nodes_;       // depth first, node 0 the root
  std::vector<std::uint32_t> order_;  // leaf slot -> index into the scene's spheres
  int depth_ = 0;                     // interior levels
};

// 1 / d per component, with zero components replaced by a tiny signed value so that the slab
// test never computes 0 * infinity.
inline glm::vec3 safe_inverse(const glm::vec3& d) {
  glm::vec3 inv;
  for (int k = 0; k < 3; ++k) {
    const float c = std::abs(d[k]) < 1e-20f ? std::copysign(1e-20f, d[k]) : d[k];
    inv[k] = 1.0f / c;
  }
  return inv;
}

// How far the slab test's float arithmetic can misplace a ray that starts at o: rounding o to
// float and subtracting it from a box corner each err by up to half an ulp of |o|, which the
// boxes' own padding (scaled by the box) does not cover for a ray from far away. 2^-20 |o| is 16
// such ulps: every box is grown by it, so the float test never culls a box the ray enters.
inline float origin_margin(const glm::vec3& o) {
  return std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)}) * 0x1p-20f;
}

// The slab test both backends use, in float on both: does the ray (origin o, inverse direction
// inv_d) enter child `c` (0 left, 1 right) of node n, its box grown by `margin` on every side,
// before t_max and leave it after t_min? Returns the entry distance, or a negative value to cull.
// Node boxes are padded for float rounding when they are built; `margin` (origin_margin) covers
// the ray's side. The CPU's SSE test of both children (cpu/bvh_world.cpp) and the shader's vec4
// test do the same float operations, lane by lane.
inline float ray_box_entry(const glm::vec3& o, const glm::vec3& inv_d, const bvh_node& n, int c,
                           float t_min, float t_max, float margin) {
  const glm::vec4* const axes[3] = {&n.x, &n.y, &n.z};
  float enter = t_min, leave = t_max;
  for (int k = 0; k < 3; ++k) {
    const float t0 = ((*axes[k])[c] - margin - o[k]) * inv_d[k];
    const float t1 = ((*axes[k])[c + 2] + margin - o[k]) * inv_d[k];
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
  }
  return enter <= leave ? enter : -1.0f;
}

}  // namespace rtvk
