// An instance's way into its group's space and back, for both backends: the ray carried in by
// the inverse placement (its direction not renormalized, so the same t reaches the same point),
// and a hit found there carried back (the point on the scene's ray, the normal by the inverse
// transpose, which keeps the side a ray comes from, the offset grown by the placement's stretch);
// and the scan order every search keeps, instances after the scene's own objects.
#ifndef RTVK_INSTANCE_SPACE_H
#define RTVK_INSTANCE_SPACE_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// The order of the lesson's linear scan, which every search of rtvk reproduces: the scene's own
// objects in scene order, then each instance's in its group's order. An exact tie between two
// hits goes to the later one, so a BVH, the driver's acceleration structure and the scan find
// the same object whatever order they test in. Both backends' searches keep their nearest hit
// with this one rule (host/cpu/bvh_world.cpp, shaders/world.glsl).

// "No instance": a hit on the scene's own objects is reached through instance 0; instance k of
// the scene's list is k + 1. Both backends count so.
#define RTVK_OWN_OBJECTS 0u

// Whether a hit at the nearest distance so far, on object `index` (its place in its list's scan
// order) reached through `inst`, replaces the nearest hit (`best_index` through `best_inst`;
// best_index -1: none yet): it does when it comes later in the scan.
inline bool later_in_scan(uint inst, int index, uint best_inst, int best_index) {
  return inst > best_inst || (inst == best_inst && index > best_index);
}

// A placement as the two functions below read it, by rows.
struct instance_frame {
  precise real3 to_group_x;       // first row of the inverse placement's linear part
  precise real3 to_group_y;       // second row
  precise real3 to_group_z;       // third row
  precise real3 to_group_offset;  // its translation: -inverse(linear) * placement offset
  precise real3 normal_x;         // first row of the normal matrix (the inverse's transpose)
  precise real3 normal_y;         // second row
  precise real3 normal_z;         // third row
  precise real stretch;           // a bound on how far the placement stretches (Frobenius norm)
};

// The ray in the group's space, at the same instant.
inline ray to_group(instance_frame f, ray r) {
  precise real3 o = real3(dot3(f.to_group_x, r.origin), dot3(f.to_group_y, r.origin),
                          dot3(f.to_group_z, r.origin)) +
                    f.to_group_offset;
  precise real3 d = real3(dot3(f.to_group_x, r.direction), dot3(f.to_group_y, r.direction),
                          dot3(f.to_group_z, r.direction));
  return ray(o, d, r.time);
}

// A tangent (hit_record::tangent) of a hit whose normal was n in the group's space, carried
// back where that normal became `normal` (unit): by the placement's linear part M, as any
// direction in the surface. The frame keeps M's inverse and the normal matrix N = M^-T, not M;
// but t = cross(b, n) for the unit t perpendicular to the unit n and b = cross(n, t), and
// M cross(b, n) = cross(N b, N n) / det(N), N n being along `normal`. A mirroring placement
// (det < 0) turns the frame over, so the handedness flips with it.
inline precise real4 carry_tangent(instance_frame f, real3 n, real4 tangent, real3 normal) {
  precise real3 b = cross3(n, real3(tangent));
  precise real3 nb = real3(dot3(f.normal_x, b), dot3(f.normal_y, b), dot3(f.normal_z, b));
  precise real det = dot3(f.normal_x, cross3(f.normal_y, f.normal_z));
  precise real side = det < real(0.0) ? real(-1.0) : real(1.0);
  precise real3 t = cross3(nb, normal);
  precise real3 along = t - dot3(normal, t) * normal;  // perpendicular again, after rounding
  precise real len = length3(along);
  if (!(len > real(0.0) && is_finite(len))) return real4(0.0);
  return real4((side / len) * along, side * tangent.w);
}

// A record made in the group's space, at t, carried back to the scene's ray r.
inline void carry_back(instance_frame f, ray r, real t, precise INOUT(hit_record) rec) {
  rec.p = ray_at(r, t);
  precise real3 n = rec.normal;
  rec.normal = unit_vector(real3(dot3(f.normal_x, n), dot3(f.normal_y, n), dot3(f.normal_z, n)));
  if (rec.tangent.w != real(0.0)) rec.tangent = carry_tangent(f, n, rec.tangent, rec.normal);
  precise real offset = rec.offset * f.stretch + flat_offset(rec.p, r);
  rec.offset = offset;
}

RTVK_KERNELS_END

#endif  // RTVK_INSTANCE_SPACE_H
