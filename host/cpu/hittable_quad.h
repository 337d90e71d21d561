#pragma once
#include "hit_quad.h"
#include "hittable.h"
#include "quad.h"

namespace rtvk {

// A scene quad as a hittable, for the lesson's hittable_list: the book's quad, its plane
// precomputed once.
class hittable_quad final : public hittable {
 public:
  explicit hittable_quad(const quad& q) : g_(q.geometry()), material_(uint(q.material)) {}

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override {
    double t;
    real2 uv;
    if (!hit_quad(g_, r, t_min, t_max, t, uv)) return false;
    record_quad_hit(g_, material_, r, t, rec);
    return true;
  }

 private:
  quad_geometry g_;  // corner, edges and plane
  uint material_;    // index into the scene's materials
};

}  // namespace rtvk
