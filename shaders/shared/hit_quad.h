// The second book's quadrilateral: a corner Q and two edges u and v span a parallelogram; the
// ray meets its plane, and the plane coordinates (alpha, beta) of the point say whether it is
// inside. Both backends test quads (and boxes, six quads) with these two functions.
#ifndef RTVK_HIT_QUAD_H
#define RTVK_HIT_QUAD_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// A quad with the book's precomputed plane: what a hit test reads.
struct quad_geometry {
  precise real3 Q;       // a corner, scene units
  precise real3 u;       // the edge from Q to the next corner, scene units
  precise real3 v;       // the other edge from Q, scene units
  precise real3 normal;  // unit normal, cross(u, v) normalized: the front side
  precise real3 w;       // cross(u, v) / |cross(u, v)|^2: plane coordinates from offsets
  precise real D;        // dot(normal, Q): the plane is dot(normal, p) = D
};

// The book's quad constructor: the plane through Q spanned by u and v.
inline quad_geometry make_quad(real3 Q, real3 u, real3 v) {
  quad_geometry q;
  q.Q = Q;
  q.u = u;
  q.v = v;
  precise real3 n = cross3(u, v);
  q.normal = unit_vector(n);
  q.D = dot3(q.normal, Q);
  q.w = divide(n, dot3(n, n));
  return q;
}

// True, and the hit's t and plane coordinates (alpha along u, beta along v, each in [0, 1]),
// when the ray meets the quad at some t in [t_min, t_max]; t = 0 when it does not.
inline bool hit_quad(quad_geometry q, ray r, real t_min, real t_max, precise OUT(real) t,
                     precise OUT(real2) uv) {
  t = real(0.0);
  uv = real2(0.0);
  precise real denom = dot3(q.normal, r.direction);
  // Parallel to the plane (the book's 1e-8), or a NaN direction: no hit.
  if (!(abs(denom) >= real(1e-8))) return false;
  precise real root = (q.D - dot3(q.normal, r.origin)) / denom;
  if (!(is_finite(root) && t_min <= root && root <= t_max)) return false;
  precise real3 planar = ray_at(r, root) - q.Q;
  precise real alpha = dot3(q.w, cross3(planar, q.v));
  precise real beta = dot3(q.w, cross3(q.u, planar));
  if (!(real(0.0) <= alpha && alpha <= real(1.0) && real(0.0) <= beta && beta <= real(1.0)))
    return false;
  t = root;
  uv = real2(alpha, beta);
  return true;
}

// The record of a hit at t on the quad; its texture coordinates are the plane coordinates
// (alpha, beta), found again as hit_quad finds them.
inline void record_quad_hit(quad_geometry q, uint material, ray r, real t,
                            precise INOUT(hit_record) rec) {
  rec.t = t;
  rec.p = ray_at(r, t);
  precise real3 planar = rec.p - q.Q;
  rec.uv = real2(dot3(q.w, cross3(planar, q.v)), dot3(q.w, cross3(q.u, planar)));
  rec.color = real4(1.0);
  rec.uv1 = rec.uv;
  rec.tangent = real4(0.0);  // no tangents
  set_face_normal(rec, r, q.normal);
  rec.material = material;
  rec.offset = flat_offset(rec.p, r);
}

RTVK_KERNELS_END

#endif  // RTVK_HIT_QUAD_H
