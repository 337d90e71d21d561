#pragma once
#include <cstdint>
#include <vector>

#include "hittable.h"
#include "shared_types.h"
#include "sphere.h"

namespace rtvk {

// A bounding volume hierarchy over spheres, built with binned SAH and flattened depth first into
// one node array (gpu::bvh_node, from the header shared with the shaders). The CPU traverses it
// here; the shader traverses the very same arrays. Hits are identical to a linear scan over the
// spheres in order: the nearest root wins, and on an exact tie the later sphere, as in
// hittable_list.
class bvh final : public hittable {
 public:
  explicit bvh(std::vector<sphere> spheres);

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;

  const std::vector<gpu::bvh_node>& nodes() const { return nodes_; }
  const std::vector<std::uint32_t>& index() const { return index_; }
  const std::vector<sphere>& spheres() const { return spheres_; }
  int depth() const { return depth_; }  // levels, root = 1

  // Most spheres in one leaf; the tree never exceeds this depth (the GPU's stack fits it).
  static constexpr int max_leaf = 4;
  static constexpr int max_depth = RTVK_BVH_STACK - 2;

 private:
  std::vector<sphere> spheres_;       // in scene order
  std::vector<gpu::bvh_node> nodes_;  // node 0 is the root (absent when there are no spheres)
  std::vector<std::uint32_t> index_;  // leaf slot -> index into spheres_
  int depth_ = 0;                     // levels in the tree
};

// The slab test both backends use: does the ray (origin o, inverse direction inv_d) enter the box
// before t_max and leave it after t_min? Returns the entry distance, or a negative value to cull.
double ray_box_entry(const glm::dvec3& o, const glm::dvec3& inv_d, const gpu::bvh_node& n,
                     double t_min, double t_max);

// 1 / d per component, with zero components replaced by a tiny signed value so that the slab
// test never computes 0 * infinity.
glm::dvec3 safe_inverse(const glm::dvec3& d);

}  // namespace rtvk
