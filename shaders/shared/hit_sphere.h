// The sphere hit, in the two halves a search over many spheres needs: the nearest root in an
// interval (hit_sphere), and the record of the winner (record_hit).
#ifndef RTVK_HIT_SPHERE_H
#define RTVK_HIT_SPHERE_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// Where a moving sphere's center is at `time` (seconds), from its center at time 0 and its
// velocity (center at time 1 minus center at time 0): linear, before 0 and after 1 too.
inline precise real3 moved_center(real3 center, real3 velocity, real time) {
  return center + time * velocity;
}

// Solves |origin + t*dir - center|^2 = radius^2 with the half-b form of the quadratic: true, and
// the nearest root in [t_min, t_max] in `t`, when there is one (t = 0 when there is none).
inline bool hit_sphere(real3 center, real radius, ray r, real t_min, real t_max,
                       precise OUT(real) t) {
  t = real(0.0);
  precise real3 oc = r.origin - center;
  precise real a = dot3(r.direction, r.direction);
  precise real half_b = dot3(oc, r.direction);
  // half_b^2 - a*c, written as a * (radius^2 - |l|^2) with l the offset from the center to the
  // line's closest point: the same number without subtracting two large, nearly equal squares.
  // In float (the GPU) the lesson's form loses most digits for small, distant spheres.
  precise real3 l = oc - (half_b / a) * r.direction;
  precise real discriminant = a * (radius * radius - dot3(l, l));
  // A degenerate ray (zero, infinite or NaN direction) makes this NaN or infinite: no hit. The
  // finiteness tests are explicit (is_finite tests bits on the GPU), not left to NaN failing
  // comparisons, which a driver may assume never happens.
  if (!is_finite(discriminant) || discriminant < real(0.0)) return false;
  precise real sqrtd = sqrt(discriminant);

  // The nearer root first; the farther one only when the nearer is out of range. A root that is
  // not a finite number inside the interval is no hit (infinity, from overflow, would pass
  // `<= t_max` when t_max is infinite).
  precise real root = (-half_b - sqrtd) / a;
  if (!(is_finite(root) && t_min <= root && root <= t_max)) {
    root = (-half_b + sqrtd) / a;
    if (!(is_finite(root) && t_min <= root && root <= t_max)) return false;
  }
  t = root;
  return true;
}

// A sphere's texture coordinates at the unit vector n from its center (the book's get_sphere_uv):
// u the angle around the y axis from -x, v the angle from -y, each over [0, 1].
inline precise real2 sphere_uv(real3 n) {
  precise real theta = acos(max(real(-1.0), min(real(1.0), -n.y)));
  precise real phi = atan2(-n.z, n.x) + pi;
  return real2(phi / (real(2.0) * pi), theta / pi);
}

// The record of a hit at t on the sphere; its texture coordinates only `with_uv` (two inverse
// trigonometric functions a hit: only scenes with image textures pay for them).
inline void record_hit(real3 center, real radius, uint material, ray r, real t, bool with_uv,
                       precise INOUT(hit_record) rec) {
  rec.t = t;
  rec.p = ray_at(r, t);
  precise real3 outward_normal = divide(rec.p - center, radius);
  set_face_normal(rec, r, outward_normal);
  rec.material = material;
  rec.uv = with_uv ? sphere_uv(outward_normal) : real2(0.0);
  rec.color = real4(1.0);
  rec.uv1 = rec.uv;
  rec.tangent = real4(0.0);  // no tangents
  // About eight float ulps of the largest coordinate involved -- the sphere's, and the ray's
  // origin's, which p = origin + t * direction inherits the rounding of -- covers the GPU's
  // rounding (ScatterOrigin.RaysLeavingASphereStartOutsideIt...).
  precise real extent = max(max(abs(center.x), abs(center.y)), abs(center.z));
  precise real reach = max(max(abs(r.origin.x), abs(r.origin.y)), abs(r.origin.z));
  rec.offset = (extent + radius + reach) * real(1.0 / 1048576.0);  // 2^-20
}

RTVK_KERNELS_END

#endif  // RTVK_HIT_SPHERE_H
