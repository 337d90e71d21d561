// The glTF 2.0 metallic-roughness BSDF (the specification's appendix B) and its KHR_materials_*
// layers, one source for both backends: evaluate, sample and density, in the shading frame.
//
// The frame: z is the shading normal at the hit, facing the side the ray came from, so the
// outgoing direction wo (toward where the ray came from) has wo.z > 0; wi with wi.z > 0 is
// reflection, wi.z < 0 transmission. Both are unit vectors. The caller builds the frame (onb) and
// turns directions in and out of it.
//
// SKELETON: the functions below are a cosine-weighted Lambertian of base_color standing in for
// the model until it lands; evaluate, density and sample are consistent with each other, so every
// statistical test written against this interface already holds for it.
#ifndef RTVK_PBR_H
#define RTVK_PBR_H
#include "kernel_lang.h"
#include "random.h"

RTVK_KERNELS_BEGIN

// A PBR material's parameters at one hit, its textures applied (linear values; gpu_pbr and
// host/scene/pbr_material.h give their meanings and defaults).
struct pbr_surface {
  real3 base_color;          // linear RGB: factor x texture x vertex color
  real metallic;             // 0 dielectric to 1 metal
  real roughness;            // perceptual, 0 to 1: GGX alpha = roughness^2
  real eta;                  // index of refraction below the surface over above it, as this ray
                             // sees it: the material's ior entering, 1 / ior leaving
  real specular;             // KHR_materials_specular: strength of the dielectric's specular
  real3 specular_color;      // KHR_materials_specular: F0 tint, linear
  real transmission;         // KHR_materials_transmission: 0 to 1
  bool thin;                 // thin-walled (thickness 0): transmitted rays do not bend
  real clearcoat;            // KHR_materials_clearcoat: 0 to 1
  real clearcoat_roughness;  // perceptual, 0 to 1
  real3 clearcoat_normal;    // the coat's unit normal in this frame (0, 0, 1: the base's)
  real3 sheen_color;         // KHR_materials_sheen: linear; 0: no sheen
  real sheen_roughness;      // perceptual, 0 to 1
};

// A pbr_surface with glTF's defaults for every extension and these core parameters.
inline pbr_surface pbr_surface_of(real3 base_color, real metallic, real roughness) {
  pbr_surface m;
  m.base_color = base_color;
  m.metallic = metallic;
  m.roughness = roughness;
  m.eta = real(1.5);
  m.specular = real(1.0);
  m.specular_color = real3(1.0);
  m.transmission = real(0.0);
  m.thin = true;
  m.clearcoat = real(0.0);
  m.clearcoat_roughness = real(0.0);
  m.clearcoat_normal = real3(0.0, 0.0, 1.0);
  m.sheen_color = real3(0.0);
  m.sheen_roughness = real(0.0);
  return m;
}

// f(wo, wi) |wi.z|: the BSDF times the cosine at wi, per steradian. Delta lobes (a smooth
// surface's mirror or refraction) are not in it: only pbr_sample finds those.
inline precise real3 pbr_eval(pbr_surface m, real3 wo, real3 wi) {
  if (wo.z <= real(0.0) || wi.z <= real(0.0)) return real3(0.0);
  return m.base_color * (wi.z * real(0.31830988618379067154));
}

// The density per steradian with which pbr_sample draws wi given wo (its non-delta lobes).
inline precise real pbr_pdf(pbr_surface m, real3 wo, real3 wi) {
  if (wo.z <= real(0.0) || wi.z <= real(0.0)) return real(0.0);
  return wi.z * real(0.31830988618379067154);
}

// Draws wi given wo from three uniform numbers u in [0, 1): weight is f |wi.z| / pdf, the factor
// a path's throughput takes. delta: wi came from a delta lobe (pdf is then that lobe's choice
// probability, and no other density may be mixed with it). False: no direction (absorbed).
inline bool pbr_sample(pbr_surface m, real3 wo, real3 u, precise OUT(real3) wi,
                       precise OUT(real3) weight, precise OUT(real) pdf, OUT(bool) delta) {
  delta = false;
  precise real r = sqrt(u.y);
  precise real phi = real(6.283185307179586) * u.z;
  wi = real3(r * cos(phi), r * sin(phi), sqrt(max(real(0.0), real(1.0) - u.y)));
  pdf = wi.z * real(0.31830988618379067154);
  weight = m.base_color;
  return wo.z > real(0.0) && pdf > real(0.0);
}

RTVK_KERNELS_END

#endif  // RTVK_PBR_H
