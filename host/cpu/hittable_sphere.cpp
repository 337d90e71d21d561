#include "hittable_sphere.h"

#include <algorithm>
#include <cmath>

namespace rtvk {

// Solves |origin + t*dir - center|^2 = radius^2 with the half-b form of the quadratic.
bool hit_distance(const sphere& s, const ray& r, double t_min, double t_max, double& t) {
  const vec3 oc = r.origin() - s.center;
  const double a = glm::dot(r.direction(), r.direction());
  const double half_b = glm::dot(oc, r.direction());
  // half_b^2 - a*c, written as a * (radius^2 - |l|^2) with l the offset from the center to the
  // line's closest point: the same number without subtracting two large, nearly equal squares.
  // In float (the GPU) the lesson's form loses most digits for small, distant spheres.
  const vec3 l = oc - (half_b / a) * r.direction();
  const double discriminant = a * (s.radius * s.radius - glm::dot(l, l));
  if (discriminant < 0) return false;
  const double sqrtd = std::sqrt(discriminant);

  // The nearer root first; the farther one only when the nearer is out of range. A root that is
  // not a finite number inside the interval is no hit: NaN (a degenerate ray: zero or infinite
  // direction) fails every comparison, and infinity (overflow) would pass `<= t_max` when t_max
  // is infinite.
  const auto usable = [&](double t) { return t_min <= t && t <= t_max && std::isfinite(t); };
  double root = (-half_b - sqrtd) / a;
  if (!usable(root)) {
    root = (-half_b + sqrtd) / a;
    if (!usable(root)) return false;
  }
  t = root;
  return true;
}

void record_hit(const sphere& s, const ray& r, double t, hit_record& rec) {
  rec.t = t;
  rec.p = r.at(rec.t);
  rec.set_face_normal(r, divide(rec.p - s.center, s.radius));
  rec.material = s.material;
  // About eight float ulps of the largest coordinate involved: covers the GPU's rounding.
  const double extent =
      std::max({std::abs(s.center.x), std::abs(s.center.y), std::abs(s.center.z)});
  rec.offset = (extent + s.radius) * 0x1p-20;
}

bool hittable_sphere::hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
  double t;
  if (!hit_distance(s_, r, t_min, t_max, t)) return false;
  record_hit(s_, r, t, rec);
  return true;
}

}  // namespace rtvk
