#pragma once
// The book's hittable interface. The ray and hit_record are the shared kernels' (ray.h).
#include "vec3.h"

namespace rtvk {

class hittable {
 public:
  virtual ~hittable() = default;
  // True when r hits the surface at some t in [t_min, t_max]; rec then holds the nearest such hit.
  virtual bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const = 0;
};

}  // namespace rtvk
