#pragma once
#include "disk.h"
#include "hit_disk.h"
#include "hittable.h"

namespace rtvk {

// A scene disk as a hittable, for the lesson's hittable_list: its plane and axes precomputed
// once, as hittable_quad does.
class hittable_disk final : public hittable {
 public:
  explicit hittable_disk(const disk& d) : g_(d.geometry()), material_(uint(d.material)) {}

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    double t;
    if (!hit_disk(g_, r, t_min, t_max, t)) return false;
    record_disk_hit(g_, material_, r, t, rec);
    return true;
  }

 private:
  disk_geometry g_;  // center, plane and axes
  uint material_;    // index into the scene's materials
};

}  // namespace rtvk
