// The scene file's PBR materials (`"type": "pbr"`): pbr_material's parameters by their own names,
// each map beside its factor as `NAME_texture` (a texture object, as `emission_texture`), read
// and written side by side. docs/scene-format.md lists them.
#include <cmath>

#include "format.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

// A factor of pbr_material in a range: its name, where it is, its bounds.
struct pbr_number {
  const char* name;
  double pbr_material::*field;
  double lo, hi;  // the range it may take
};

const pbr_number numbers[] = {
    {"metallic", &pbr_material::metallic, 0, 1},
    {"roughness", &pbr_material::roughness, 0, 1},
    {"normal_scale", &pbr_material::normal_scale, -1e6, 1e6},
    {"ior", &pbr_material::ior, 1, 100},
    {"specular", &pbr_material::specular, 0, 1},
    {"transmission", &pbr_material::transmission, 0, 1},
    {"thickness", &pbr_material::thickness, 0, 1e30},
    {"clearcoat", &pbr_material::clearcoat, 0, 1},
    {"clearcoat_roughness", &pbr_material::clearcoat_roughness, 0, 1},
    {"clearcoat_normal_scale", &pbr_material::clearcoat_normal_scale, -1e6, 1e6},
    {"sheen_roughness", &pbr_material::sheen_roughness, 0, 1},
};

// A color of pbr_material: an albedo (each channel in [0, 1]) or, for specular_color (glTF lets
// its factor pass 1), any value >= 0.
struct pbr_color {
  const char* name;
  color pbr_material::*field;
  bool unbounded;
};

const pbr_color colors[] = {
    {"specular_color", &pbr_material::specular_color, true},
    {"attenuation_color", &pbr_material::attenuation_color, false},
    {"sheen_color", &pbr_material::sheen_color, false},
};

// A map: its field's name and the texture index it sets.
struct pbr_texture_field {
  const char* name;
  int pbr_material::*field;
};

const pbr_texture_field maps[] = {
    {"metallic_roughness_texture", &pbr_material::metallic_roughness_texture},
    {"normal_texture", &pbr_material::normal_texture},
    {"specular_texture", &pbr_material::specular_texture},
    {"specular_color_texture", &pbr_material::specular_color_texture},
    {"transmission_texture", &pbr_material::transmission_texture},
    {"thickness_texture", &pbr_material::thickness_texture},
    {"clearcoat_texture", &pbr_material::clearcoat_texture},
    {"clearcoat_roughness_texture", &pbr_material::clearcoat_roughness_texture},
    {"clearcoat_normal_texture", &pbr_material::clearcoat_normal_texture},
    {"sheen_color_texture", &pbr_material::sheen_color_texture},
    {"sheen_roughness_texture", &pbr_material::sheen_roughness_texture},
};

const pbr_material defaults{};

}  // namespace

std::vector<std::string> pbr_fields() {
  std::vector<std::string> out{"attenuation_distance"};
  for (const pbr_number& n : numbers) out.push_back(n.name);
  for (const pbr_color& c : colors) out.push_back(c.name);
  for (const pbr_texture_field& m : maps) out.push_back(m.name);
  return out;
}

void read_pbr(const scene_reader& r, const json& j, const std::string& p, scene& s, material& m) {
  pbr_material& q = m.pbr;
  for (const pbr_number& n : numbers)
    if (j.contains(n.name)) q.*n.field = r.number_in(j[n.name], p + "/" + n.name, n.lo, n.hi);
  for (const pbr_color& c : colors)
    if (j.contains(c.name))
      q.*c.field = c.unbounded ? r.radiance(j[c.name], p + "/" + c.name)
                               : r.albedo(j[c.name], p + "/" + c.name);
  if (j.contains("attenuation_distance")) {  // absent: infinite, no attenuation
    const std::string at = p + "/attenuation_distance";
    q.attenuation_distance = r.number(j["attenuation_distance"], at);
    if (!(q.attenuation_distance > 0))
      r.fail(at, "expected a distance > 0, got " + format_number(q.attenuation_distance));
  }
  for (const pbr_texture_field& t : maps) {
    if (!j.contains(t.name)) continue;
    const json& v = j[t.name];
    const std::string at = p + "/" + t.name;
    if (!v.is_object() || (v.contains("type") && v["type"] == "solid"))
      r.fail(at, "expected a texture object, got " + r.type_of(v));
    material holder;  // the texture's index lands in its `texture`
    read_color_or_texture(r, v, at, false, s, holder);
    q.*t.field = holder.texture;
  }
}

void write_pbr(const scene& s, const material& m, json& j) {
  const pbr_material& q = m.pbr;
  for (const pbr_number& n : numbers)
    if (q.*n.field != defaults.*n.field) j[n.name] = q.*n.field;
  for (const pbr_color& c : colors)
    if (q.*c.field != defaults.*c.field) j[c.name] = vec_json(q.*c.field);
  if (std::isfinite(q.attenuation_distance)) j["attenuation_distance"] = q.attenuation_distance;
  for (const pbr_texture_field& t : maps)
    if (q.*t.field >= 0) j[t.name] = texture_json(s.textures[std::size_t(q.*t.field)]);
}

}  // namespace rtvk::scene_json
