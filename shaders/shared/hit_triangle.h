// Triangles, watertight: Woop, Benthin and Wald's ray-triangle test (JCGT 2013). The ray is
// sheared so that it runs along +z from the origin; each vertex is moved into that frame the same
// way whichever triangle it belongs to, and each edge's 2D edge function is computed by the same
// products, so the two triangles on a shared edge see exactly opposite values there: a ray through
// an edge or a vertex of a closed mesh hits at least one of the triangles around it (a point on
// an edge counts as inside). Both backends test triangles with these functions.
#ifndef RTVK_HIT_TRIANGLE_H
#define RTVK_HIT_TRIANGLE_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// A ray prepared once for all its triangle tests: the axes of its frame and the shear.
struct sheared_ray {
  uint kx, ky, kz;      // kz: the axis the direction is largest along; kx, ky the others, in
                        // the order that keeps the triangles' winding
  precise real3 shear;  // (dx / dz, dy / dz, 1 / dz) along those axes
};

inline sheared_ray shear_ray(ray r) {
  sheared_ray s;
  precise real3 a = abs(r.direction);
  s.kz = a.x >= a.y ? (a.x >= a.z ? 0u : 2u) : (a.y >= a.z ? 1u : 2u);
  s.kx = s.kz == 2u ? 0u : s.kz + 1u;
  s.ky = s.kx == 2u ? 0u : s.kx + 1u;
  if (r.direction[s.kz] < real(0.0)) {
    uint k = s.kx;
    s.kx = s.ky;
    s.ky = k;
  }
  precise real dz = r.direction[s.kz];
  s.shear = real3(r.direction[s.kx] / dz, r.direction[s.ky] / dz, real(1.0) / dz);
  return s;
}

// A vertex relative to the ray's origin, in the sheared frame (x, y), and its unscaled depth (z).
inline precise real3 sheared_vertex(real3 p, ray r, sheared_ray s) {
  precise real3 a = p - r.origin;
  return real3(a[s.kx] - s.shear.x * a[s.kz], a[s.ky] - s.shear.y * a[s.kz], a[s.kz]);
}

// The edge function of the edge from p to q in the sheared frame: twice the signed area of the
// triangle (origin, p, q). Swapping p and q negates it exactly (the same two products).
inline precise real edge_function(real3 p, real3 q) {
  return q.x * p.y - q.y * p.x;
}

// True, and the hit's t and barycentric weights (of a, b, c; summing to one), when the ray meets
// the triangle at some t in [t_min, t_max]; t = 0 when it does not. Both sides are hit.
inline bool hit_triangle(real3 a, real3 b, real3 c, ray r, sheared_ray s, real t_min, real t_max,
                         precise OUT(real) t, precise OUT(real3) weights) {
  t = real(0.0);
  weights = real3(0.0);
  precise real3 A = sheared_vertex(a, r, s);
  precise real3 B = sheared_vertex(b, r, s);
  precise real3 C = sheared_vertex(c, r, s);
  precise real U = edge_function(B, C);
  precise real V = edge_function(C, A);
  precise real W = edge_function(A, B);
  // Outside when the signs differ; zero (on an edge) counts as inside for both neighbors.
  if ((U < real(0.0) || V < real(0.0) || W < real(0.0)) &&
      (U > real(0.0) || V > real(0.0) || W > real(0.0)))
    return false;
  precise real det = U + V + W;
  if (!(is_finite(det) && det != real(0.0))) return false;  // seen edge on, or a NaN ray
  precise real T = U * (s.shear.z * A.z) + V * (s.shear.z * B.z) + W * (s.shear.z * C.z);
  precise real root = T / det;
  if (!(is_finite(root) && t_min <= root && root <= t_max)) return false;
  t = root;
  weights = real3(U / det, V / det, W / det);
  return true;
}

// The record of a hit at t on the triangle: its geometric normal (cross(b - a, c - a), the front
// side counter-clockwise) decides the side; the normal shaded is `shading` (unit: the vertex
// normals blended, or the geometric one for a flat triangle) turned to that side; uv its texture
// coordinates (triangle_uv).
inline void record_triangle_hit(real3 a, real3 b, real3 c, real3 shading, real2 uv, uint material,
                                ray r, real t, precise INOUT(hit_record) rec) {
  rec.t = t;
  rec.uv = uv;
  rec.color = real4(1.0);    // the vertex colors, where the triangle has some, are set after
  rec.uv1 = uv;              // and so is a second set of texture coordinates
  rec.tangent = real4(0.0);  // and its tangents
  rec.p = ray_at(r, t);
  precise real3 geometric = unit_vector(cross3(b - a, c - a));
  set_face_normal(rec, r, geometric);
  rec.normal = rec.front_face ? shading : -shading;
  rec.material = material;
  rec.offset = flat_offset(rec.p, r);
}

// The vertex normals n0, n1, n2 blended by barycentric weights and normalized: smooth shading.
inline precise real3 blend_normals(real3 n0, real3 n1, real3 n2, real3 weights) {
  return unit_vector(weights.x * n0 + weights.y * n1 + weights.z * n2);
}

// The normal a hit on the triangle (a, b, c) is shaded with: its vertex normals n0, n1, n2
// blended by the hit's weights where `blended`, else the geometric normal (flat).
inline precise real3 shading_normal(real3 a, real3 b, real3 c, bool blended, real3 n0, real3 n1,
                                    real3 n2, real3 weights) {
  if (blended) return blend_normals(n0, n1, n2, weights);
  return unit_vector(cross3(b - a, c - a));
}

// A triangle's texture coordinates at barycentric weights `weights`: the vertices' uv0, uv1, uv2
// blended where the mesh gives them (`given`), else the weights of b and c, as a quad's plane
// coordinates are its corners' (the vertices at (0, 0), (1, 0) and (0, 1)).
inline precise real2 triangle_uv(bool given, real2 uv0, real2 uv1, real2 uv2, real3 weights) {
  if (!given) return real2(weights.y, weights.z);
  return weights.x * uv0 + weights.y * uv1 + weights.z * uv2;
}

// A triangle's vertex colors c0, c1, c2 (linear RGBA) blended by barycentric weights: the color
// at the hit, which multiplies the material's color and alpha.
inline precise real4 blend_colors(real4 c0, real4 c1, real4 c2, real3 weights) {
  return weights.x * c0 + weights.y * c1 + weights.z * c2;
}

// The tangent at a hit (hit_record::tangent) from a triangle's vertex tangents t0, t1, t2 (xyz
// unit, w the handedness, glTF's TANGENT): blended by barycentric weights, made perpendicular to
// the record's shading normal (Gram-Schmidt) and unit. The handedness is the first vertex's (a
// triangle's vertices agree: generation splits vertices at mirrored uv), negated on a back-face
// hit, where the record's normal is the surface's turned over: cross(normal, t) * w stays the
// surface's +v. Zero where the blend lies along the normal (degenerate input).
inline precise real4 blend_tangents(real4 t0, real4 t1, real4 t2, real3 weights, hit_record rec) {
  precise real3 t = weights.x * real3(t0) + weights.y * real3(t1) + weights.z * real3(t2);
  precise real3 n = rec.normal;
  precise real3 along = t - dot3(n, t) * n;
  precise real len = length3(along);
  if (!(len > real(0.0) && is_finite(len))) return real4(0.0);
  real w = t0.w < real(0.0) ? real(-1.0) : real(1.0);
  return real4(divide(along, len), rec.front_face ? w : -w);
}

RTVK_KERNELS_END

#endif  // RTVK_HIT_TRIANGLE_H
