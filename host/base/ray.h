#pragma once
#include "vec3.h"

namespace rtvk {

// P(t) = origin + t * direction.
class ray {
 public:
  ray() = default;
  ray(const point3& origin, const vec3& direction) : orig(origin), dir(direction) {}

  point3 origin() const { return orig; }
  vec3 direction() const { return dir; }
  point3 at(double t) const { return orig + t * dir; }

 private:
  point3 orig{};  // where the ray starts, scene units
  vec3 dir{};     // not normalized: t is measured in lengths of this vector
};

}  // namespace rtvk
