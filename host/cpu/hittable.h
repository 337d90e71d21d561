#pragma once
#include "ray.h"

namespace rtvk {

struct hit_record {
  point3 p{};               // where the ray hit, scene units
  vec3 normal{};            // unit surface normal, facing against the ray
  double t = 0.0;           // ray parameter of the hit
  bool front_face = false;  // true when the ray arrived from outside the surface
  int material = 0;         // index into the scene's materials
  double offset = 0.0;      // how far a ray leaving p starts off the surface, scene units

  // Where a ray leaving the hit along `direction` starts: lifted off the surface to the side it
  // leaves to, by more than float rounding can misplace p on a large sphere. Without it, float
  // hit points on the book's radius-1000 ground land inside it often enough that rays leaving
  // it hit it again ("acne"), and the GPU's image drifts from the CPU's.
  point3 scatter_origin(const vec3& direction) const {
    return p + (glm::dot(direction, normal) >= 0 ? offset : -offset) * normal;
  }

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
