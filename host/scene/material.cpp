#include "material.h"

namespace rtvk {
namespace {

// Fields: type, name, then whether it reads albedo, fuzz and ir, and whether it draws random
// numbers.
constexpr material_kind kinds[] = {
    {material_type::normal, "normal", false, false, false, false},
    {material_type::lambertian, "lambertian", true, false, false, true},
    {material_type::metal, "metal", true, true, false, true},
    {material_type::dielectric, "dielectric", false, false, true, true},
    {material_type::flat, "flat", true, false, false, false},
    {material_type::diffuse_light, "diffuse_light", true, false, false, false},
    {material_type::isotropic, "isotropic", true, false, false, true},
    // Its parameters beyond the base color (albedo) are pbr_material's (scene_file_pbr.cpp).
    {material_type::pbr, "pbr", true, false, false, true},
};

}  // namespace

const material_kind& kind_of(material_type t) {
  for (const material_kind& k : kinds)
    if (k.type == t) return k;
  return kinds[0];
}

std::optional<material_kind> kind_named(std::string_view name) {
  for (const material_kind& k : kinds)
    if (k.name == name) return k;
  return std::nullopt;
}

std::string kind_names() {
  std::string out;
  const std::size_t n = std::size(kinds);
  for (std::size_t i = 0; i < n; ++i)
    out += (i == 0 ? "" : i + 1 == n ? " or " : ", ") + std::string(kinds[i].name);
  return out;
}

std::string type_name(material_type t) {
  return std::string(kind_of(t).name);
}

}  // namespace rtvk
