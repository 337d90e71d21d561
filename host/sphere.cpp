#include "sphere.h"

#include <cmath>

namespace rtvk {

// Solves |origin + t*dir - center|^2 = radius^2 with the half-b form of the quadratic.
bool sphere::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  const vec3 oc = r.origin() - center;
  const double a = glm::dot(r.direction(), r.direction());
  const double half_b = glm::dot(oc, r.direction());
  const double c = glm::dot(oc, oc) - radius * radius;
  const double discriminant = half_b * half_b - a * c;
  if (discriminant < 0) return false;
  const double sqrtd = std::sqrt(discriminant);

  // The nearer root first; the farther one only when the nearer is out of range.
  double root = (-half_b - sqrtd) / a;
  if (root < t_min || t_max < root) {
    root = (-half_b + sqrtd) / a;
    if (root < t_min || t_max < root) return false;
  }

  rec.t = root;
  rec.p = r.at(rec.t);
  rec.set_face_normal(r, divide(rec.p - center, radius));
  rec.material = material;
  return true;
}

}  // namespace rtvk
