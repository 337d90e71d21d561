#pragma once
#include "hittable.h"

namespace rtvk {

class sphere final : public hittable {
 public:
  sphere() = default;
  sphere(const point3& center, double radius, int material = 0)
      : center(center), radius(radius), material(material) {}

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;

  // The two halves of hit: the nearest root in [t_min, t_max] (false when there is none), and
  // the record of a hit at t. A search over many spheres fills the record only for the winner.
  bool hit_distance(const ray& r, double t_min, double t_max, double& t) const;
  void record_hit(const ray& r, double t, hit_record& rec) const;

  point3 center{};      // scene units
  double radius = 0.0;  // scene units, > 0
  int material = 0;     // index into the scene's materials
};

}  // namespace rtvk
