#pragma once
#include <cstdint>
#include <string>

#include "vec3.h"

namespace rtvk {

enum class material_type : std::uint32_t {
  normal = 0,      // the lesson's shading: color = 0.5 * (normal + 1); no bounce
  lambertian = 1,  // diffuse
  metal = 2,       // mirror, blurred by fuzz
  dielectric = 3,  // glass: refracts, reflects by Schlick, total internal reflection
};

// A surface's optics. One flat struct (rather than a class per material) so the GPU copy is the
// same data; each renderer's scatter functions (cpu/scatter.h, shaders/material.glsl) carry the
// book's names and math.
struct material {
  material_type type = material_type::normal;
  color albedo{1, 1, 1};  // fraction of light kept per channel (lambertian, metal)
  double fuzz = 0;        // metal: radius of the reflection's blur sphere, 0 to 1
  double ir = 1.5;        // dielectric: index of refraction
};

std::string type_name(material_type t);

}  // namespace rtvk
