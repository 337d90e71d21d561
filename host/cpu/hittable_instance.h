#pragma once
#include <memory>

#include "hittable.h"
#include "scene_tree.h"

namespace rtvk {

// The book's `translate` and `rotate_y`, for any placement: a group of objects (stored once, one
// hittable shared by every instance) hit by the ray carried into the group's space, the hit
// carried back. The same t reaches the same point in both spaces (the direction is not
// renormalized); the normal goes back by the inverse transpose, so the side a ray comes from
// (front_face) is the same in both.
class hittable_instance final : public hittable {
 public:
  hittable_instance(std::shared_ptr<const hittable> group, const transform& placement)
      : group_(std::move(group)), frame_(frame_of(placement)) {}

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    if (!group_->hit(to_group(frame_, r), t_min, t_max, rec)) return false;
    carry_back(frame_, r, rec.t, rec);
    return true;
  }

 private:
  std::shared_ptr<const hittable> group_;  // the group's objects, in its own space
  instance_frame frame_;                   // the way into that space and back
};

}  // namespace rtvk
