// The scene file's punctual lights (docs/scene-format.md, docs/lighting.md): "lights", point,
// spot and directional lights and suns in KHR_lights_punctual's units (candela, lux), read and
// written side by side.
#include <cmath>

#include "format.h"
#include "light_sources.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

// A light's kind by its "type", naming the field and the value when it is none of the three.
punctual_kind kind_of(const scene_reader& r, const json& j, const std::string& p) {
  const json& type = r.required(j, p, "type");
  const std::string t = type.is_string() ? type.get<std::string>() : "";
  for (const punctual_kind k :
       {punctual_kind::point, punctual_kind::spot, punctual_kind::directional})
    if (t == punctual_kind_name(k)) return k;
  r.fail(p + "/type", "expected \"point\", \"spot\" or \"directional\", got " +
                          (type.is_string() ? "\"" + t + "\"" : r.type_of(type)));
}

// A direction that can be normalized: not zero (its length's square not below 1e-24).
vec3 direction_of(const scene_reader& r, const json& j, const std::string& p) {
  const vec3 d = r.vector3(r.required(j, p, "direction"), p + "/direction");
  if (!(glm::dot(d, d) >= 1e-24))
    r.fail(p + "/direction", "expected a direction, got the zero vector " + vec_json(d).dump());
  return d;
}

// A spot's cones, degrees off its direction: 0 <= inner <= outer <= 90 (glTF's rule).
void read_cones(const scene_reader& r, const json& j, const std::string& p, punctual_light& l) {
  if (j.contains("inner_cone_angle"))
    l.inner_cone = r.number_in(j["inner_cone_angle"], p + "/inner_cone_angle", 0, 90);
  if (j.contains("outer_cone_angle"))
    l.outer_cone = r.number_in(j["outer_cone_angle"], p + "/outer_cone_angle", 0, 90);
  if (l.inner_cone > l.outer_cone)
    r.fail(p + "/inner_cone_angle", "expected at most outer_cone_angle (" +
                                        format_number(l.outer_cone) + "), got " +
                                        format_number(l.inner_cone));
}

punctual_light read_light(const scene_reader& r, const json& j, const std::string& p) {
  punctual_light l;
  l.kind = kind_of(r, j, p);
  if (l.kind == punctual_kind::point)
    r.only_fields(j, p, {"type", "name", "position", "color", "intensity"});
  else if (l.kind == punctual_kind::spot)
    r.only_fields(j, p,
                  {"type", "name", "position", "direction", "color", "intensity",
                   "inner_cone_angle", "outer_cone_angle"});
  else
    r.only_fields(j, p, {"type", "name", "direction", "color", "intensity", "angular_diameter"});
  if (j.contains("name")) {
    if (!j["name"].is_string())
      r.fail(p + "/name", "expected a string, got " + r.type_of(j["name"]));
    l.name = j["name"].get<std::string>();
  }
  if (l.kind != punctual_kind::directional)
    l.position = r.vector3(r.required(j, p, "position"), p + "/position");
  if (l.kind != punctual_kind::point) l.direction = direction_of(r, j, p);
  if (j.contains("color")) l.tint = r.radiance(j["color"], p + "/color");
  if (j.contains("intensity")) {
    l.intensity = r.number(j["intensity"], p + "/intensity");
    if (!(l.intensity >= 0))
      r.fail(p + "/intensity", "expected an intensity >= 0, got " + format_number(l.intensity));
  }
  if (l.kind == punctual_kind::spot) read_cones(r, j, p, l);
  if (j.contains("angular_diameter")) {
    l.angular_diameter = r.number(j["angular_diameter"], p + "/angular_diameter");
    if (!(l.angular_diameter >= 0 && l.angular_diameter < 180))
      r.fail(p + "/angular_diameter",
             "expected degrees in [0, 180), got " + format_number(l.angular_diameter));
  }
  return l;
}

}  // namespace

// /lights: [{"type": "point" | "spot" | "directional", ...}], each checked field by field.
void read_lights(const scene_reader& r, const json& root, scene& s) {
  read_array(r, root, "", "lights", [&](const json& j, const std::string& p) {
    if (s.punctual_lights.size() >= max_punctual_lights)
      r.fail(p, "more than " + std::to_string(max_punctual_lights) + " lights");
    s.punctual_lights.push_back(read_light(r, j, p));
  });
}

void write_lights(const scene& s, json& root) {
  if (s.punctual_lights.empty()) return;
  json lights = json::array();
  for (const punctual_light& l : s.punctual_lights) {
    json j = {{"type", punctual_kind_name(l.kind)}};
    if (!l.name.empty()) j["name"] = l.name;
    if (l.kind != punctual_kind::directional) j["position"] = vec_json(l.position);
    if (l.kind != punctual_kind::point) j["direction"] = vec_json(l.direction);
    j["color"] = vec_json(l.tint);
    j["intensity"] = l.intensity;
    if (l.kind == punctual_kind::spot) {
      j["inner_cone_angle"] = l.inner_cone;
      j["outer_cone_angle"] = l.outer_cone;
    }
    if (l.kind == punctual_kind::directional) j["angular_diameter"] = l.angular_diameter;
    lights.push_back(j);
  }
  root["lights"] = lights;
}

}  // namespace rtvk::scene_json
