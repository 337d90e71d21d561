// The scene file's placements and instancing: transforms (scale, rotate, translate, or a
// matrix), the named groups of objects, and the instances that place them; read and written
// side by side.
#include <algorithm>
#include <cmath>

#include "format.h"
#include "object_group.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

// A placement as a matrix: 12 numbers (3 rows of x, y, z, translation) or 16 (a 4x4 whose last
// row must be 0 0 0 1), row-major, as exporters write a node's world matrix.
transform read_matrix(const scene_reader& r, const json& m, const std::string& p) {
  if (!m.is_array() || (m.size() != 12 && m.size() != 16))
    r.fail(p, "expected 12 or 16 numbers (row-major), got " +
                  (m.is_array() ? std::to_string(m.size()) + " values" : r.type_of(m)));
  double v[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  for (std::size_t k = 0; k < m.size(); ++k) v[k] = r.number(m[k], p + "/" + std::to_string(k));
  if (v[12] != 0 || v[13] != 0 || v[14] != 0 || v[15] != 1)
    r.fail(p, "the last row must be 0 0 0 1 (an affine placement, no projection)");
  transform t;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) t.linear[col][row] = v[4 * row + col];
    t.offset[row] = v[4 * row + 3];
  }
  return t;
}

}  // namespace

// An object's placement: {"scale": s or [x, y, z], "rotate": {"axis": [x, y, z], "degrees": d},
// "translate": [x, y, z]}, each optional, applied in that order; or {"matrix": [...]}.
transform read_transform(const scene_reader& r, const json& j, const std::string& p) {
  r.only_fields(j, p, {"scale", "rotate", "translate", "matrix"});
  if (j.contains("matrix")) {
    for (const char* other : {"scale", "rotate", "translate"})
      if (j.contains(other))
        r.fail(p + "/" + other, "a transform is a matrix or scale, rotate and translate, not both");
    const transform t = read_matrix(r, j["matrix"], p + "/matrix");
    if (const std::optional<std::string> why = degenerate(t))
      r.fail(p, "the transform cannot place anything: " + *why);
    return t;
  }
  vec3 scale(1), axis(0, 1, 0), offset(0);
  double degrees = 0;
  if (j.contains("scale")) {
    const json& sc = j["scale"];
    scale = sc.is_number() ? vec3(r.number(sc, p + "/scale")) : r.vector3(sc, p + "/scale");
  }
  if (j.contains("rotate")) {
    const std::string rp = p + "/rotate";
    r.only_fields(j["rotate"], rp, {"axis", "degrees"});
    axis = r.vector3(r.required(j["rotate"], rp, "axis"), rp + "/axis");
    if (!(glm::length(axis) > 0) || !std::isfinite(glm::length(axis)))
      r.fail(rp + "/axis", "expected a nonzero finite axis");
    degrees = r.number(r.required(j["rotate"], rp, "degrees"), rp + "/degrees");
  }
  if (j.contains("translate")) offset = r.vector3(j["translate"], p + "/translate");
  const transform t = make_transform(scale, axis, degrees, offset);
  if (const std::optional<std::string> why = degenerate(t))
    r.fail(p, "the transform cannot place anything: " + *why);
  return t;
}

transform optional_transform(const scene_reader& r, const json& j, const std::string& p) {
  return j.contains("transform") ? read_transform(r, j["transform"], p + "/transform")
                                 : transform{};
}

// A placement as the 12 numbers read_matrix reads (row-major, translation last in each row).
json matrix_json(const transform& t) {
  json m = json::array();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) m.push_back(t.linear[col][row]);
    m.push_back(t.offset[row]);
  }
  return m;
}

namespace {

// The groups instances place, by name: each read as the objects of a scene (spheres, quads,
// boxes, triangles, meshes) with the scene's materials; a mesh file's own materials are added
// to the scene's.
void read_named_groups(const scene_reader& r, const json& groups, scene& s) {
  if (!groups.is_object())
    r.fail("/groups", "expected an object of named groups, got " + r.type_of(groups));
  for (const auto& [name, j] : groups.items()) {
    const std::string p = "/groups/" + escape_pointer(name);
    if (!j.is_object()) r.fail(p, "expected an object, got " + r.type_of(j));
    const std::vector<const char*> fields = object_fields();
    r.only_fields(j, p, {fields.begin(), fields.end()});
    scene g;
    g.materials = std::move(s.materials);
    read_objects(r, j, p, g);
    s.materials = std::move(g.materials);
    // A glTF's KHR_lights_punctual inside a group: instances do not place lights (yet).
    if (!g.punctual_lights.empty())
      s.warnings.push_back(r.file() + ": " + p + ": " + std::to_string(g.punctual_lights.size()) +
                           " punctual lights of the group's mesh files are dropped (instances do "
                           "not place lights)");
    for (std::size_t k = 0; k < g.spheres.size(); ++k)
      if (g.spheres[k].center1)
        r.fail(p + "/spheres/" + std::to_string(k) + "/center1",
               "a group's spheres cannot move (instances place still objects)");
    for (std::size_t k = 0; k < g.spheres.size(); ++k)
      if (g.spheres[k].sampled)
        r.fail(p + "/spheres/" + std::to_string(k) + "/sample",
               "lights sampling aims only at the scene's own objects, not a group's");
    for (std::size_t k = 0; k < g.quads.size(); ++k)
      if (g.quads[k].sampled)
        r.fail(p + "/quads/" + std::to_string(k) + "/sample",
               "lights sampling aims only at the scene's own objects, not a group's");
    object_group group;
    static_cast<shape_lists&>(group) = std::move(g);  // the objects read, without the rest
    group.name = name;
    if (empty(group)) r.fail(p, "the group has no object (nothing an instance could place)");
    s.groups.push_back(std::move(group));
  }
}

// Each instance: a group and its placement.
void read_instances(const scene_reader& r, const json& root, scene& s) {
  read_array(r, root, "", "instances", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"group", "transform"});
    const json& name = r.required(j, p, "group");
    const auto found = std::find_if(s.groups.begin(), s.groups.end(), [&](const object_group& g) {
      return name.is_string() && g.name == name.get<std::string>();
    });
    if (found == s.groups.end()) {
      std::string known;
      for (const object_group& g : s.groups) known += (known.empty() ? "" : ", ") + g.name;
      r.fail(p + "/group",
             "expected the name of a group (" +
                 (known.empty() ? std::string("the scene has none") : known) + "), got " +
                 (name.is_string() ? "\"" + name.get<std::string>() + "\"" : r.type_of(name)));
    }
    if (s.instances.size() >= std::size_t(RTVK_LEAF_INDEX_MASK))
      r.fail(p, "more than " + std::to_string(std::size_t(RTVK_LEAF_INDEX_MASK)) +
                    " instances (a BVH leaf reference's 29 bits, less one)");
    s.instances.push_back({std::uint32_t(found - s.groups.begin()), optional_transform(r, j, p)});
  });
}

}  // namespace

void read_groups(const scene_reader& r, const json& root, scene& s) {
  if (!root.contains("groups") && !root.contains("instances")) return;
  if (root.contains("groups")) read_named_groups(r, root["groups"], s);
  read_instances(r, root, s);
}

void write_groups(const scene& s, json& root) {
  if (s.groups.empty()) return;
  json groups = json::object();
  for (const object_group& g : s.groups) {
    json objects = json::object();
    write_objects(objects, s, g);
    groups[g.name] = objects;
  }
  root["groups"] = groups;
  json instances = json::array();
  for (const instance& i : s.instances) {
    json j = {{"group", s.groups[i.group].name}};
    if (!i.placement.is_identity()) j["transform"] = {{"matrix", matrix_json(i.placement)}};
    instances.push_back(j);
  }
  root["instances"] = instances;
}

}  // namespace rtvk::scene_json
