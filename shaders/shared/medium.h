// Participating media: the second book's constant_medium, a boundary (a sphere or a box, placed by
// any affine transform) filled with fog of constant density that scatters a ray at a random
// distance inside it. Both backends test a ray against every medium after their world search
// (the nearest of the world's hit and the media's scattering points wins), with these kernels.
#ifndef RTVK_MEDIUM_H
#define RTVK_MEDIUM_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "random.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// gpu_medium's fields at the compilation's precision.
struct medium_geometry {
  precise real3 to_local_x;       // rows of the inverse placement (the boundary's space)
  precise real3 to_local_y;       //
  precise real3 to_local_z;       //
  precise real3 to_local_offset;  // its translation
  uint shape;                     // RTVK_BOUNDARY_*
  precise real3 lo;               // box: minimum corner; sphere: center (local units)
  precise real3 hi;               // box: maximum corner; sphere: x is the radius
  precise real neg_inv_density;   // -1 / density, per scene unit
  uint material;                  // its phase function (an isotropic material)
  uint index;                     // among the scene's media: picks its random numbers
};

const uint dim_medium = 4u;  // bounce >= 1: where the ray scatters in a medium (its own key)
// bounce >= 1: where a shadow ray scatters in a medium (next-event estimation: its own number, so
// that the shadow ray and the path's next ray cross a medium independently)
const uint dim_shadow_medium = 15u;

// The uniform number medium `index` draws in dimension `dim` (dim_medium, dim_shadow_medium) of
// this bounce's stream: each medium a key of its own (and a pixel key of its own for the
// low-discrepancy numbers), so that two media a ray crosses scatter it independently.
inline precise float medium_random(random_stream s, uint index, uint dim) {
  uint spread = index * 0x9e3779b9u + 0x6d656469u;
  return rnd(random_stream(hash32(s.key ^ spread), s.bounce, hash32(s.pixel_key ^ spread),
                           s.sample_index, s.low_discrepancy),
             dim);
}

// Where the line of r enters and leaves a sphere (t_in <= t_out, any sign), or false.
inline bool sphere_span(real3 center, real radius, ray r, precise OUT(real) t_in,
                        precise OUT(real) t_out) {
  t_in = real(0.0);
  t_out = real(0.0);
  precise real3 oc = r.origin - center;
  precise real a = dot3(r.direction, r.direction);
  precise real half_b = dot3(oc, r.direction);
  precise real3 l = oc - (half_b / a) * r.direction;  // as hit_sphere: no cancellation
  precise real discriminant = a * (radius * radius - dot3(l, l));
  if (!is_finite(discriminant) || discriminant < real(0.0)) return false;
  precise real sqrtd = sqrt(discriminant);
  t_in = (-half_b - sqrtd) / a;
  t_out = (-half_b + sqrtd) / a;
  return is_finite(t_in) && is_finite(t_out);
}

// One axis of the slab test: narrows [t_in, t_out] to where the line is between lo and hi.
inline bool narrow_to_slab(real o, real d, real lo, real hi, precise INOUT(real) t_in,
                           precise INOUT(real) t_out) {
  if (d == real(0.0)) return lo <= o && o <= hi;  // parallel: inside the slab or never
  precise real t0 = (lo - o) / d;
  precise real t1 = (hi - o) / d;
  t_in = max(t_in, min(t0, t1));
  t_out = min(t_out, max(t0, t1));
  return t_in <= t_out;
}

// Where the line of r enters and leaves the box [lo, hi], or false.
inline bool box_span(real3 lo, real3 hi, ray r, precise OUT(real) t_in, precise OUT(real) t_out) {
  t_in = real(-3.402823466e+38);
  t_out = real(3.402823466e+38);
  return narrow_to_slab(r.origin.x, r.direction.x, lo.x, hi.x, t_in, t_out) &&
         narrow_to_slab(r.origin.y, r.direction.y, lo.y, hi.y, t_in, t_out) &&
         narrow_to_slab(r.origin.z, r.direction.z, lo.z, hi.z, t_in, t_out);
}

// The book's constant_medium::hit: the stretch of r inside the boundary, within [t_min, t_max],
// and a distance into it drawn from the exponential distribution of the density (from the
// uniform number u); true, and the scattering point in rec, when that distance ends inside.
inline bool hit_medium(medium_geometry m, ray r, real t_min, real t_max, real u,
                       precise INOUT(hit_record) rec) {
  precise ray local = ray(real3(dot3(m.to_local_x, r.origin), dot3(m.to_local_y, r.origin),
                                dot3(m.to_local_z, r.origin)) +
                              m.to_local_offset,
                          real3(dot3(m.to_local_x, r.direction), dot3(m.to_local_y, r.direction),
                                dot3(m.to_local_z, r.direction)),
                          r.time);
  precise real t_in, t_out;
  bool crosses = m.shape == RTVK_BOUNDARY_SPHERE ? sphere_span(m.lo, m.hi.x, local, t_in, t_out)
                                                 : box_span(m.lo, m.hi, local, t_in, t_out);
  if (!crosses) return false;
  t_in = max(t_in, t_min);
  t_out = min(t_out, t_max);
  if (!(t_in < t_out) || !(u > real(0.0))) return false;
  precise real ray_length = length3(r.direction);
  precise real distance_inside = (t_out - t_in) * ray_length;
  precise real hit_distance = m.neg_inv_density * log(u);
  if (!(hit_distance <= distance_inside)) return false;
  rec.t = t_in + hit_distance / ray_length;
  rec.p = ray_at(r, rec.t);
  rec.normal = real3(1.0, 0.0, 0.0);  // arbitrary: the isotropic phase function ignores it
  rec.front_face = true;
  rec.material = m.material;
  rec.offset = real(0.0);
  rec.uv = real2(0.0);
  rec.color = real4(1.0);
  rec.uv1 = rec.uv;
  rec.tangent = real4(0.0);  // no tangents
  return true;
}

RTVK_KERNELS_END

#endif  // RTVK_MEDIUM_H
