#include "obj_material.h"

#include <algorithm>
#include <cmath>

namespace rtvk {
namespace {

double unit(double x) {
  return std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0);
}

// An emitted radiance: finite and not negative, however strong.
double radiance(double x) {
  return std::isfinite(x) && x > 0 ? x : 0.0;
}

}  // namespace

material mtl_material(const tinyobj::material_t& m) {
  material out;
  out.emission = color(radiance(m.emission[0]), radiance(m.emission[1]), radiance(m.emission[2]));
  // tinyobjloader reads Tr as 1 - d when the material has no d.
  out.opacity = unit(m.dissolve);
  if (out.opacity < 1) out.alpha = alpha_mode::blend;
  const bool refracts = m.illum == 4 || m.illum == 6 || m.illum == 7 || m.illum == 9;
  if (refracts) {
    out.type = material_type::dielectric;
    out.ir = m.ior > 1 && std::isfinite(m.ior) ? m.ior : 1.5;
    out.alpha = alpha_mode::opaque;  // glass is already see-through: its d is not drawn twice
    out.opacity = 1;
    return out;
  }
  if (m.metallic >= 0.5 || m.illum == 3) {
    out.type = material_type::metal;
    const tinyobj::real_t* c = m.metallic >= 0.5 ? m.diffuse : m.specular;
    out.albedo = color(unit(c[0]), unit(c[1]), unit(c[2]));
    out.fuzz = unit(m.roughness);
    return out;
  }
  out.type = material_type::lambertian;
  out.albedo = color(unit(m.diffuse[0]), unit(m.diffuse[1]), unit(m.diffuse[2]));
  return out;
}

}  // namespace rtvk
