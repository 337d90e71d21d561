// The lesson's ray and hit record, and the vector helpers every kernel uses: one source for the
// C++ backends and the shaders (kernel_lang.h).
#ifndef RTVK_RAY_H
#define RTVK_RAY_H
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

const real pi = real(3.1415926535897932385);

// glm's dot and length, operation for operation: (x * x' + y * y') + z * z', no fused
// multiply-adds (GLSL's built-ins leave the order and the fusing to the device).
inline precise real dot3(real3 a, real3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
// The cross product, term by term (GLSL's built-in leaves fusing to the device).
inline precise real3 cross3(real3 a, real3 b) {
  return real3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline precise real length3(real3 v) {
  return sqrt(dot3(v, v));
}

// The lesson divides as (1/t) * v: the reference image is bit for bit the lesson's.
inline precise real3 divide(real3 v, real t) {
  return (real(1.0) / t) * v;
}
inline precise real3 unit_vector(real3 v) {
  return divide(v, length3(v));
}

// P(t) = origin + t * direction, at one instant: moving objects are where they are at `time`.
struct ray {
  precise real3 origin;     // where the ray starts, scene units
  precise real3 direction;  // not normalized: t is measured in lengths of this vector
  precise real time;        // the instant it samples, seconds (the camera's shutter draws it)
#ifdef __cplusplus
  ray() = default;
  ray(real3 o, real3 d, real tm = real(0.0)) : origin(o), direction(d), time(tm) {}
#endif
};

inline precise real3 ray_at(ray r, real t) {
  return r.origin + t * r.direction;
}

struct hit_record {
  precise real3 p;        // where the ray hit, scene units
  precise real3 normal;   // unit surface normal, facing against the ray
  precise real t;         // ray parameter of the hit
  bool front_face;        // the ray arrived from outside the surface
  uint material;          // index into the scene's materials
  precise real offset;    // how far a ray leaving p starts off the surface, scene units
  precise real2 uv;       // texture coordinates of p on the object (image textures read them)
  precise real4 color;    // the vertex colors blended at p (linear RGBA), 1 where none: multiply
                          // the material's color and alpha
  precise real2 uv1;      // the second texture coordinates of p, which the emission texture
                          // reads: uv where the object has no second set
  precise real4 tangent;  // xyz: the unit tangent at p (along +u, perpendicular to normal); w:
                          // +1 or -1, the bitangent being cross(normal, xyz) * w with normal as
                          // stored (facing the ray); all 0 where the object has no tangents
};

// Where a ray leaving the hit along `direction` starts: lifted off the surface to the side it
// leaves to, by more than float rounding can misplace p on a large sphere. Without it, float hit
// points on the book's radius-1000 ground land inside it often enough that rays leaving it hit it
// again ("acne"), and the GPU's image drifts from the CPU's.
inline precise real3 scatter_origin(hit_record rec, real3 direction) {
  precise real facing = dot3(direction, rec.normal);
  return rec.p + (facing >= real(0.0) ? rec.offset : -rec.offset) * rec.normal;
}

// The largest coordinate magnitude of p.
inline precise real max_abs3(real3 p) {
  return max(max(abs(p.x), abs(p.y)), abs(p.z));
}

// How far a ray leaving a flat surface (a quad, a triangle) at p starts off it: eight float ulps
// of the largest coordinate involved, the point's and the ray origin's it inherits rounding from
// (as record_hit's sphere offset, without a radius).
inline precise real flat_offset(real3 p, ray r) {
  return (max_abs3(p) + max_abs3(r.origin)) * real(1.0 / 1048576.0);  // 2^-20
}

// Stores the normal so that it always opposes the incoming ray.
inline void set_face_normal(precise INOUT(hit_record) rec, ray r, real3 outward_normal) {
  precise real facing = dot3(r.direction, outward_normal);
  rec.front_face = facing < real(0.0);
  rec.normal = rec.front_face ? outward_normal : -outward_normal;
}

RTVK_KERNELS_END

#endif  // RTVK_RAY_H
