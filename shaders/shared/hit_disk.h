// A disk: the points of a plane within `radius` of a center (a lamp's face, a turntable, a
// coin, the cap of a cylinder). The ray meets the plane as a quad's does (hit_quad.h); the point
// is inside when its squared distance from the center is at most radius^2. Both backends test
// disks with these two functions, and the hardware paths with the same one from their
// intersection shader.
#ifndef RTVK_HIT_DISK_H
#define RTVK_HIT_DISK_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// A disk with its plane and in-plane axes precomputed: what a hit test reads.
struct disk_geometry {
  precise real3 center;  // scene units
  precise real3 normal;  // unit normal: the front side
  precise real3 u;       // unit axis in the plane: texture u grows along it
  precise real3 v;       // cross(normal, u): texture v grows along it
  precise real radius;   // scene units, > 0
  precise real D;        // dot(normal, center): the plane is dot(normal, p) = D
};

// The disk through `center` facing `normal` (any length but zero). Its axes are the
// branchless orthonormal basis of Duff et al. 2017 ("Building an Orthonormal Basis,
// Revisited"), so a disk's texture turns with its normal without a seam.
inline disk_geometry make_disk(real3 center, real3 normal, real radius) {
  disk_geometry d;
  d.center = center;
  d.normal = unit_vector(normal);
  precise real s = d.normal.z >= real(0.0) ? real(1.0) : real(-1.0);
  precise real a = real(-1.0) / (s + d.normal.z);
  precise real b = d.normal.x * d.normal.y * a;
  d.u = real3(real(1.0) + s * d.normal.x * d.normal.x * a, s * b, -s * d.normal.x);
  d.v = real3(b, s + d.normal.y * d.normal.y * a, -d.normal.y);
  d.radius = radius;
  d.D = dot3(d.normal, center);
  return d;
}

// True, and the hit's t, when the ray meets the disk at some t in [t_min, t_max]; t = 0 when
// it does not.
inline bool hit_disk(disk_geometry d, ray r, real t_min, real t_max, precise OUT(real) t) {
  t = real(0.0);
  precise real denom = dot3(d.normal, r.direction);
  // Parallel to the plane (the quad's 1e-8), or a NaN direction: no hit.
  if (!(abs(denom) >= real(1e-8))) return false;
  precise real root = (d.D - dot3(d.normal, r.origin)) / denom;
  if (!(is_finite(root) && t_min <= root && root <= t_max)) return false;
  precise real3 planar = ray_at(r, root) - d.center;
  precise real reach = d.radius * d.radius;
  if (!(dot3(planar, planar) <= reach)) return false;
  t = root;
  return true;
}

// The record of a hit at t on the disk. Its texture coordinates map the disk's square of side
// 2 radius onto [0, 1]^2 along u and v (the center at (0.5, 0.5)): an image is drawn on it
// undistorted, as on a quad.
inline void record_disk_hit(disk_geometry d, uint material, ray r, real t,
                            precise INOUT(hit_record) rec) {
  rec.t = t;
  rec.p = ray_at(r, t);
  precise real3 planar = rec.p - d.center;
  precise real scale = real(0.5) / d.radius;
  rec.uv = real2(real(0.5) + dot3(planar, d.u) * scale, real(0.5) + dot3(planar, d.v) * scale);
  rec.color = real4(1.0);
  rec.uv1 = rec.uv;
  rec.tangent = real4(0.0);  // no tangents
  set_face_normal(rec, r, d.normal);
  rec.material = material;
  rec.offset = flat_offset(rec.p, r);
}

RTVK_KERNELS_END

#endif  // RTVK_HIT_DISK_H
