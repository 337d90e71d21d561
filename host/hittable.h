#pragma once
#include "ray.h"

namespace rtvk {

struct hit_record {
  point3 p{};               // where the ray hit, scene units
  vec3 normal{};            // unit surface normal, facing against the ray
  double t = 0.0;           // ray parameter of the hit
  bool front_face = false;  // true when the ray arrived from outside the surface
  int material = 0;         // index into the scene's materials

  // Stores the normal so that it always opposes the incoming ray.
  void set_face_normal(const ray& r, const vec3& outward_normal) {
    front_face = glm::dot(r.direction(), outward_normal) < 0;
    normal = front_face ? outward_normal : -outward_normal;
  }
};

class hittable {
 public:
  virtual ~hittable() = default;
  // True when r hits the surface at some t in [t_min, t_max]; rec then holds the nearest such hit.
  virtual bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const = 0;
};

}  // namespace rtvk
