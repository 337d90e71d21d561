#pragma once
#include <limits>

#include "vec3.h"

namespace rtvk {

// A physically based material's parameters beyond those every material has: glTF 2.0's
// metallic-roughness model and its KHR_materials_* extensions, with glTF's defaults. The base
// color is the material's albedo (times its texture and the vertex colors), the emission, alpha
// and culling are the material's own. Each texture is an index into the scene's textures (-1:
// none); it multiplies its factor, read from the channel glTF names. The shared kernels' view of
// the same: gpu_pbr (appearance_types.h) and pbr_surface (pbr.h).
struct pbr_material {
  double metallic = 1;                  // 0 dielectric to 1 metal
  double roughness = 1;                 // perceptual, 0 to 1 (GGX alpha = roughness^2)
  int metallic_roughness_texture = -1;  // G: roughness, B: metallic (linear)
  int normal_texture = -1;              // tangent-space normal map (linear)
  double normal_scale = 1;              // scales the normal map's x and y
  double ior = 1.5;                     // KHR_materials_ior: index of refraction
  double specular = 1;                  // KHR_materials_specular: strength of the specular
  int specular_texture = -1;            // A: specular
  color specular_color{1, 1, 1};        // KHR_materials_specular: F0 tint, linear
  int specular_color_texture = -1;      // RGB: specular_color (sRGB)
  double transmission = 0;              // KHR_materials_transmission: 0 to 1
  int transmission_texture = -1;        // R: transmission
  double thickness = 0;                 // KHR_materials_volume: 0 thin-walled, else a closed
                                        // volume whose inside attenuates (scene units)
  int thickness_texture = -1;           // G: thickness
  color attenuation_color{1, 1, 1};     // KHR_materials_volume: what white becomes after
                                        // attenuation_distance inside, linear
  double attenuation_distance = std::numeric_limits<double>::infinity();  // scene units
  double clearcoat = 0;                  // KHR_materials_clearcoat: 0 to 1
  int clearcoat_texture = -1;            // R: clearcoat
  double clearcoat_roughness = 0;        // perceptual, 0 to 1
  int clearcoat_roughness_texture = -1;  // G: clearcoat_roughness
  int clearcoat_normal_texture = -1;     // the coat's normal map (linear)
  double clearcoat_normal_scale = 1;     // scales its x and y
  color sheen_color{0, 0, 0};            // KHR_materials_sheen: linear; 0: none
  int sheen_color_texture = -1;          // RGB: sheen_color (sRGB)
  double sheen_roughness = 0;            // perceptual, 0 to 1
  int sheen_roughness_texture = -1;      // A: sheen_roughness
};

// Calls f with each of p's texture indices, by reference (Pbr: pbr_material, const or not).
template <class Pbr, class F>
void for_each_pbr_texture(Pbr& p, F&& f) {
  for (auto field : {&pbr_material::metallic_roughness_texture, &pbr_material::normal_texture,
                     &pbr_material::specular_texture, &pbr_material::specular_color_texture,
                     &pbr_material::transmission_texture, &pbr_material::thickness_texture,
                     &pbr_material::clearcoat_texture, &pbr_material::clearcoat_roughness_texture,
                     &pbr_material::clearcoat_normal_texture, &pbr_material::sheen_color_texture,
                     &pbr_material::sheen_roughness_texture})
    f(p.*field);
}

}  // namespace rtvk
