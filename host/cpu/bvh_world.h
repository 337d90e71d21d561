#pragma once
#include <vector>

#include "bvh.h"
#include "hittable.h"
#include "sphere.h"
#include "wide_bvh.h"

namespace rtvk {

// The scene's spheres behind a BVH (accel/bvh.h): hits are identical to a linear scan over the
// spheres in order -- the nearest root wins, and on an exact tie the later sphere in the scene,
// as in hittable_list.
class bvh_world final : public hittable {
 public:
  // Built on `threads` threads (0: one per core).
  // Built on `threads` threads (0: one per core), bounding moving spheres over `motion`.
  explicit bvh_world(const std::vector<sphere>& spheres, int threads = 0, time_span motion = {});

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;

 private:
  // A sphere as the search reads it: what a still one needs, in 40 bytes (a moving one's
  // velocity is kept apart, so scenes where nothing moves read no more than before).
  struct leaf_sphere {
    point3 center;  // at time 0, scene units
    double radius;  // scene units
    int material;   // index into the scene's materials
  };

  // The binary tree (the GPU's) is built, collapsed and dropped: the CPU keeps only these.
  std::vector<std::uint32_t> order_;  // leaf slot -> index into the scene's spheres
  wide_bvh wide_;                     // the tree collapsed four wide: what the CPU traverses
  std::vector<leaf_sphere> spheres_;  // in leaf order: slot k is scene sphere order_[k]
  std::vector<vec3> velocities_;      // in leaf order; empty when no sphere moves
};

}  // namespace rtvk
