// Ground truth beside the image (rtvk render --aov): what the ray through a pixel's center
// (center_ray, camera_rays.h) hits first, measured alike on both backends. docs/aov.md has the
// channels and their units.
#ifndef RTVK_AOV_H
#define RTVK_AOV_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "ray.h"
#include "scatter.h"

RTVK_KERNELS_BEGIN

// The albedo channel: the color a material reflects at the hit (its albedo or texture, as the
// renderers shade it); glass passes all light, white; a lamp its emitted radiance; the normal
// material the color it draws.
inline precise real3 aov_albedo(uint type, real3 color, hit_record rec) {
  if (type == RTVK_MATERIAL_DIELECTRIC) return real3(1.0);
  if (type == RTVK_MATERIAL_NORMAL) return real(0.5) * (rec.normal + real3(1.0));
  return color;
}

// The hit's distance along the camera ray (|direction| t) and its z depth (along the camera's
// axis, -axis_w, from its eye), scene units.
inline precise real aov_distance(ray r, hit_record rec) {
  return rec.t * length3(r.direction);
}
inline precise real aov_depth(real3 eye, real3 axis_w, hit_record rec) {
  return -dot3(rec.p - eye, axis_w);
}

// Whether the AOVs show a hit on a surface with these material flags and this alpha: as the
// renderers count it (ray_color.h's surface_counts), a blend where its alpha is over 1/2 (the
// AOVs draw no random numbers).
inline bool aov_counts(uint type, uint flags, hit_record rec, real alpha, real cutoff) {
  if ((flags & RTVK_MATERIAL_SEE_THROUGH) == 0u) return true;
  return surface_counts(type, flags, rec.front_face, alpha, cutoff, real(0.5));
}

RTVK_KERNELS_END

#endif  // RTVK_AOV_H
