#include "obj_material.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rtvk {
namespace {

double unit(double x) {
  return std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0);
}

// An emitted radiance: finite and not negative, however strong.
double radiance(double x) {
  return std::isfinite(x) && x > 0 ? x : 0.0;
}

double mean(const tinyobj::real_t* c) {
  return (c[0] + c[1] + c[2]) / 3.0;
}

// What illum's value turns on (Blender's reading of it, obj_import_mtl.cc).
struct illum_mode {
  bool highlight = false;   // 2
  bool reflection = false;  // 3 to 8
  bool refraction = false;  // 4, 6, 7, 9: transparency (Blender draws it as alpha; rtvk refracts)
};

illum_mode mode_of(int illum) {
  illum_mode m;
  m.highlight = illum == 2;
  m.reflection = illum >= 3 && illum <= 8;
  m.refraction = illum == 4 || illum == 6 || illum == 7 || illum == 9;
  return m;
}

}  // namespace

// Each newmtl's name as tinyobjloader takes it (the rest of the line, trailing blanks and the
// line end cut), and the first word of each statement after it.
mtl_statements statements_of(const std::string& mtl_text) {
  mtl_statements out;
  std::set<std::string>* current = nullptr;
  std::istringstream in(mtl_text);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find_last_not_of(" \t\r") + 1);
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    const std::size_t end = line.find_first_of(" \t", start);
    const std::string word = line.substr(start, end == std::string::npos ? end : end - start);
    if (word == "newmtl" && end != std::string::npos)
      current = &out[line.substr(end + 1)];
    else if (current)
      current->insert(word);
  }
  return out;
}

material mtl_material(const tinyobj::material_t& m, const std::set<std::string>& given) {
  const auto has = [&](const char* s) { return given.count(s) != 0; };
  const illum_mode mode = mode_of(m.illum);
  material out;
  out.type = material_type::pbr;
  pbr_material& p = out.pbr;
  const double base = mode.refraction ? 1.0 : 0.8;  // untinted glass; Blender's default
  out.albedo =
      has("Kd") ? color(unit(m.diffuse[0]), unit(m.diffuse[1]), unit(m.diffuse[2])) : color(base);
  out.emission = color(radiance(m.emission[0]), radiance(m.emission[1]), radiance(m.emission[2]));
  // tinyobjloader reads Tr as 1 - d when the material has no d.
  out.opacity = unit(m.dissolve);
  if (out.opacity < 1) out.alpha = alpha_mode::blend;
  // Blender's Specular IOR Level, which its glTF exporter writes as KHR_materials_specular: twice
  // the level, the part above 1 in specularColorFactor (io_scene_gltf2 .../extensions/specular.py).
  const double level = 2 * unit(has("Ks") ? mean(m.specular) : mode.highlight ? 1 : 0);
  p.specular = std::min(1.0, level);
  p.specular_color = color(std::max(1.0, level));
  p.roughness =
      has("Ns")
          ? 1 - std::sqrt(std::clamp(std::isfinite(m.shininess) ? m.shininess : 0, 0.0f, 1000.0f) /
                          1000.0)
      : mode.highlight ? 0.0
                       : 1.0;
  if (has("Pr")) p.roughness = unit(m.roughness);
  p.metallic = mode.reflection && !mode.refraction ? (has("Ka") ? unit(mean(m.ambient)) : 1.0) : 0;
  if (has("Pm")) p.metallic = unit(m.metallic);
  p.ior = has("Ni") && m.ior > 0 && std::isfinite(m.ior) ? std::max(1.0, double(m.ior)) : 1.5;
  if (mode.refraction) {
    p.transmission = 1;
    out.alpha = alpha_mode::opaque;  // glass is already see-through: its d is not drawn twice
    out.opacity = 1;
  }
  if (has("Ps")) {
    p.sheen_color = color(unit(m.sheen));
    p.sheen_roughness = 0.5;
  }
  if (has("Pc")) p.clearcoat = unit(0.25 * m.clearcoat_thickness);
  p.clearcoat_roughness = has("Pcr") ? unit(m.clearcoat_roughness) : 0.03;
  return out;
}

}  // namespace rtvk
