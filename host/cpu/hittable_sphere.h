#pragma once
#include "hit_sphere.h"
#include "hittable.h"
#include "sphere.h"

namespace rtvk {

// The two halves of a sphere hit (hit_sphere.h) for a scene sphere: the nearest root in
// [t_min, t_max] (false when there is none), and the record of a hit at t. A search over many
// spheres fills the record only for the winner.
inline bool hit_distance(const sphere& s, const ray& r, double t_min, double t_max, double& t) {
  return hit_sphere(s.center_at(r.time), s.radius, r, t_min, t_max, t);
}
inline void record_hit(const sphere& s, const ray& r, double t, hit_record& rec) {
  // The lesson's list always finds a sphere's texture coordinates (the BVH only when an image
  // texture reads them): the same records either way where they are read.
  record_hit(s.center_at(r.time), s.radius, uint(s.material), r, t, true, rec);
}

// A scene sphere as a hittable, for the lesson's hittable_list.
class hittable_sphere final : public hittable {
 public:
  explicit hittable_sphere(const sphere& s) : s_(s) {}
  hittable_sphere(const point3& center, double radius, int material = 0)
      : s_(center, radius, material) {}

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;

  const sphere& data() const { return s_; }

 private:
  sphere s_;  // center, radius and material
};

}  // namespace rtvk
