// What each material does with a ray that hits it: the book's lambertian, metal and dielectric.
// Each returns false when the ray is absorbed; `s` is the stream of this bounce.
#ifndef RTVK_SCATTER_H
#define RTVK_SCATTER_H
#include "appearance_types.h"
#include "kernel_lang.h"
#include "random.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// Mirror reflection of v about the unit normal n.
inline precise real3 reflect_dir(real3 v, real3 n) {
  return v - real(2.0) * dot3(v, n) * n;
}

// Snell's law for a unit direction uv entering a surface with unit normal n (facing against uv),
// etai_over_etat = n1 / n2.
inline precise real3 refract_dir(real3 uv, real3 n, real etai_over_etat) {
  precise real cos_theta = min(dot3(-uv, n), real(1.0));
  precise real3 r_out_perp = etai_over_etat * (uv + cos_theta * n);
  precise real3 r_out_parallel = -sqrt(abs(real(1.0) - dot3(r_out_perp, r_out_perp))) * n;
  return r_out_perp + r_out_parallel;
}

// Schlick's approximation of the reflected fraction; (1 - cosine)^5 without pow.
inline precise real schlick_reflectance(real cosine, real ref_idx) {
  precise real r0 = (real(1.0) - ref_idx) / (real(1.0) + ref_idx);
  r0 = r0 * r0;
  precise real x = real(1.0) - cosine;
  precise real x2 = x * x;
  return r0 + (real(1.0) - r0) * (x2 * x2 * x);
}

inline bool scatter_lambertian(real3 albedo, ray r_in, hit_record rec, random_stream s,
                               precise OUT(real3) attenuation, precise OUT(ray) scattered) {
  precise real3 direction =
      rec.normal + random_unit_vector(real(rnd(s, dim_direction_a)), real(rnd(s, dim_direction_b)));
  // A random vector opposite the normal would give a zero direction: keep the normal instead.
  const real e = real(1e-8);
  if (abs(direction.x) < e && abs(direction.y) < e && abs(direction.z) < e) direction = rec.normal;
  scattered = ray(scatter_origin(rec, direction), direction, r_in.time);
  attenuation = albedo;
  return true;
}

inline bool scatter_metal(real3 albedo, real fuzz, ray r_in, hit_record rec, random_stream s,
                          precise OUT(real3) attenuation, precise OUT(ray) scattered) {
  precise real3 reflected = reflect_dir(unit_vector(r_in.direction), rec.normal);
  precise real3 fuzz_dir = random_in_unit_sphere(
      real(rnd(s, dim_direction_a)), real(rnd(s, dim_direction_b)), real(rnd(s, dim_fuzz_radius)));
  precise real3 direction = reflected + fuzz * fuzz_dir;
  scattered = ray(scatter_origin(rec, direction), direction, r_in.time);
  attenuation = albedo;
  precise real facing = dot3(scattered.direction, rec.normal);
  return facing > real(0.0);
}

inline bool scatter_dielectric(real ir, ray r_in, hit_record rec, random_stream s,
                               precise OUT(real3) attenuation, precise OUT(ray) scattered) {
  attenuation = real3(1.0, 1.0, 1.0);
  precise real refraction_ratio = rec.front_face ? (real(1.0) / ir) : ir;
  precise real3 unit_direction = unit_vector(r_in.direction);
  precise real cos_theta = min(dot3(-unit_direction, rec.normal), real(1.0));
  precise real sin_theta = sqrt(real(1.0) - cos_theta * cos_theta);
  bool cannot_refract = refraction_ratio * sin_theta > real(1.0);
  precise real3 direction =
      cannot_refract || schlick_reflectance(cos_theta, refraction_ratio) > real(rnd(s, dim_choice))
          ? reflect_dir(unit_direction, rec.normal)
          : refract_dir(unit_direction, rec.normal, refraction_ratio);
  scattered = ray(scatter_origin(rec, direction), direction, r_in.time);
  return true;
}

// The book's isotropic phase function: a medium scatters a ray every way alike, from the point
// inside it where it scattered (no surface to lift off).
inline bool scatter_isotropic(real3 albedo, ray r_in, hit_record rec, random_stream s,
                              precise OUT(real3) attenuation, precise OUT(ray) scattered) {
  precise real3 direction =
      random_unit_vector(real(rnd(s, dim_direction_a)), real(rnd(s, dim_direction_b)));
  scattered = ray(rec.p, direction, r_in.time);
  attenuation = albedo;
  return true;
}

// The material of type `type` (RTVK_MATERIAL_*) with these parameters: albedo for lambertian and
// metal and isotropic, fuzz for metal, ir for dielectric. The normal, flat and diffuse_light
// materials scatter nothing (ray_color shades them).
inline bool scatter(uint type, real3 albedo, real fuzz, real ir, ray r_in, hit_record rec,
                    random_stream s, precise OUT(real3) attenuation, precise OUT(ray) scattered) {
  attenuation = real3(0.0);
  scattered = r_in;
  if (type == RTVK_MATERIAL_LAMBERTIAN)
    return scatter_lambertian(albedo, r_in, rec, s, attenuation, scattered);
  if (type == RTVK_MATERIAL_METAL)
    return scatter_metal(albedo, fuzz, r_in, rec, s, attenuation, scattered);
  if (type == RTVK_MATERIAL_DIELECTRIC)
    return scatter_dielectric(ir, r_in, rec, s, attenuation, scattered);
  if (type == RTVK_MATERIAL_ISOTROPIC)
    return scatter_isotropic(albedo, r_in, rec, s, attenuation, scattered);
  return false;
}

// Which hits on a surface count at all: glTF's alpha modes and back-face culling, decided alike
// by the renderers (ray_color.h's path_passes: a ray let through goes on beyond the surface) and
// by the AOVs (aov.h).

// Surfaces one path may pass through (alpha, cull_back) before the next one counts whatever its
// alpha: no path loops forever, and each pass is a step of the GPU's loop budget.
const uint max_passes = 16u;

// Whether a hit on a surface with these material flags (RTVK_MATERIAL_*) counts: false where a
// back face is culled (never a dielectric's: a ray inside glass leaves through its back), where
// a mask's alpha is below the cutoff, and, for a blend, with probability 1 - alpha (u uniform in
// [0, 1); the AOVs pass 1/2, so a blend counts for them where alpha > 1/2).
inline bool surface_counts(uint type, uint flags, bool front_face, real alpha, real cutoff,
                           real u) {
  if ((flags & RTVK_MATERIAL_CULL_BACK) != 0u && !front_face && type != RTVK_MATERIAL_DIELECTRIC)
    return false;
  if ((flags & RTVK_MATERIAL_ALPHA_MASK) != 0u) return alpha >= cutoff;
  if ((flags & RTVK_MATERIAL_ALPHA_BLEND) != 0u) return u < alpha;
  return true;
}

RTVK_KERNELS_END

#endif  // RTVK_SCATTER_H
