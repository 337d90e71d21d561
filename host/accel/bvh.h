#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "shared_types.h"
#include "sphere.h"

namespace rtvk {

// A bounding volume hierarchy over spheres, built with binned SAH and flattened depth first into
// one node array (gpu::bvh_node, from the header shared with the shaders). Both backends traverse
// the very same arrays: the CPU in cpu/bvh_world.h, the shader in shaders/world.glsl. Leaves
// refer to spheres by their index in the scene, so hits can be kept identical to a linear scan.
class bvh {
 public:
  explicit bvh(std::span<const sphere> spheres);

  // An interior node's two child boxes, per axis: (left min, right min, left max, right max),
  // so that a traversal can test both children in one pass of 4-wide float operations.
  struct child_boxes {
    float x[4];
    float y[4];
    float z[4];
  };

  const std::vector<gpu::bvh_node>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& index() const { return index_; }
  const std::vector<child_boxes>& children() const { return children_; }

  // Most spheres in one leaf; the tree never exceeds this depth (the GPU's stack fits it).
  static constexpr int max_leaf = 1;
  static constexpr int max_depth = RTVK_BVH_STACK - 2;

 private:
  std::vector<gpu::bvh_node> nodes_;   // node 0 is the root (absent when there are no spheres)
  std::vector<std::uint32_t> index_;   // leaf slot -> index into the scene's spheres
  std::vector<child_boxes> children_;  // per node; meaningful for interior nodes
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
// inv_d) enter the box, grown by `margin` on every side, before t_max and leave it after t_min?
// Returns the entry distance, or a negative value to cull. Node boxes are padded for float
// rounding when they are built; `margin` (origin_margin) covers the ray's side.
inline float ray_box_entry(const glm::vec3& o, const glm::vec3& inv_d, const gpu::bvh_node& n,
                           float t_min, float t_max, float margin) {
  float enter = t_min, leave = t_max;
  for (int k = 0; k < 3; ++k) {
    const float t0 = (n.bounds_min[k] - margin - o[k]) * inv_d[k];
    const float t1 = (n.bounds_max[k] + margin - o[k]) * inv_d[k];
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
  }
  return enter <= leave ? enter : -1.0f;
}

}  // namespace rtvk
