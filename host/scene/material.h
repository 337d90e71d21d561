#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pbr_material.h"
#include "shared_types.h"
#include "vec3.h"

namespace rtvk {

// The kinds of material, numbered as the shaders number them (shared_types.h).
enum class material_type : std::uint32_t {
  normal = RTVK_MATERIAL_NORMAL,          // the lesson's shading: 0.5 * (normal + 1); no bounce
  lambertian = RTVK_MATERIAL_LAMBERTIAN,  // diffuse
  metal = RTVK_MATERIAL_METAL,            // mirror, blurred by fuzz
  dielectric = RTVK_MATERIAL_DIELECTRIC,  // glass: refracts, reflects by Schlick, total reflection
  flat = RTVK_MATERIAL_FLAT,              // its albedo, unlit; no bounce (geometry and colors)
  diffuse_light = RTVK_MATERIAL_DIFFUSE_LIGHT,  // a lamp: emits its color, both sides; no bounce
  isotropic = RTVK_MATERIAL_ISOTROPIC,          // a medium's phase function: scatters every way
  pbr = RTVK_MATERIAL_PBR,  // glTF's metallic-roughness model and its extensions (`pbr`)
};

// How a material's alpha (its opacity, 0 to 1) decides which hits count (glTF's alphaMode).
enum class alpha_mode : std::uint32_t {
  opaque = 0,  // every hit counts; alpha is ignored
  mask = 1,    // a hit counts where alpha >= alpha_cutoff, else the ray passes through
  blend = 2,   // a hit counts with probability alpha (stochastic transparency: unbiased)
};

// A surface's optics. One flat struct (rather than a class per material) so the GPU copy is the
// same data; what each kind does with a ray is the shared kernels' (shaders/shared/scatter.h and
// ray_color.h), which both backends compile.
struct material {
  material_type type = material_type::normal;
  color albedo{1, 1, 1};   // fraction of light kept per channel (lambertian, metal, isotropic,
                           // flat); diffuse_light: the radiance it emits, any strength
  double fuzz = 0;         // metal: radius of the reflection's blur sphere, 0 to 1
  double ir = 1.5;         // dielectric: index of refraction
  int texture = -1;        // index into the scene's textures: the color at a hit is the texture's
                           // value there instead of albedo; -1: albedo everywhere
  bool one_sided = false;  // diffuse_light: emits from its front side only (the third book's)
  // Beyond the books (glTF and MTL materials, docs/mesh-formats.md); the defaults change nothing.
  color emission{0, 0, 0};    // radiance emitted besides what it reflects, any strength (glTF
                              // emissiveFactor times emissive_strength; MTL Ke)
  int emission_texture = -1;  // index into the scene's textures: multiplies emission; -1: none
  alpha_mode alpha = alpha_mode::opaque;  // how `opacity` decides which hits count
  double opacity = 1;         // base alpha, 0 to 1: times the texture's alpha and the vertex alpha
  double alpha_cutoff = 0.5;  // mask: a hit counts where the alpha is at least this
  bool cull_back = false;     // rays that hit its back pass through (glTF doubleSided: false)
  pbr_material pbr{};         // material_type::pbr: its parameters beyond albedo (base color),
                              // texture (base color texture), emission and alpha
};

// The material's flags as the shared kernels read them (gpu_material::flags): what of its
// emission, alpha and culling is in use. A material with none of them is drawn as the books draw.
// Calls f with each of m's texture indices, by reference: its color's, its emission's and its PBR
// maps' (Material: material, const or not). -1: none.
template <class Material, class F>
void for_each_texture(Material& m, F&& f) {
  f(m.texture);
  f(m.emission_texture);
  for_each_pbr_texture(m.pbr, f);
}

inline std::uint32_t material_flags(const material& m) {
  std::uint32_t f = m.one_sided ? RTVK_MATERIAL_ONE_SIDED : 0u;
  if (m.emission != color(0, 0, 0)) f |= RTVK_MATERIAL_EMISSIVE;
  if (m.cull_back) f |= RTVK_MATERIAL_CULL_BACK;
  if (m.alpha == alpha_mode::mask) f |= RTVK_MATERIAL_ALPHA_MASK;
  if (m.alpha == alpha_mode::blend) f |= RTVK_MATERIAL_ALPHA_BLEND;
  return f;
}

// What a kind is called in scene files and which of material's parameters it reads: the one
// place the host lists the kinds (material.cpp).
struct material_kind {
  material_type type;
  std::string_view name;  // in scene files, e.g. "lambertian"
  bool albedo;            // reads a color (required in scene files; a texture may stand in)
  bool fuzz;              // reads `fuzz` (optional, default 0)
  bool ir;                // reads `ir` (required)
  bool random;            // draws random numbers: its images are Monte Carlo estimates
};

const material_kind& kind_of(material_type t);
std::optional<material_kind> kind_named(std::string_view name);
std::string kind_names();  // "normal, lambertian, metal or dielectric", for messages

std::string type_name(material_type t);

}  // namespace rtvk
