#include "hittable_sphere.h"

namespace rtvk {

bool hittable_sphere::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  double t;
  if (!hit_distance(s_, r, t_min, t_max, t)) return false;
  record_hit(s_, r, t, rec);
  return true;
}

}  // namespace rtvk
