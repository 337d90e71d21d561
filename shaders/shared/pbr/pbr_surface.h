// The parameters of pbr.h's BSDF at one hit: pbr_surface and glTF's defaults.
#ifndef RTVK_PBR_SURFACE_H
#define RTVK_PBR_SURFACE_H
#include "kernel_lang.h"

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

RTVK_KERNELS_END

#endif  // RTVK_PBR_SURFACE_H
