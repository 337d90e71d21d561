// The scene file's objects: spheres, quads, boxes, triangles, disks and mesh files, of the scene or
// of a group, each kind read by its row of object_kinds; the writer beside them writes what they
// became (a box as its six quads, a mesh as its triangles).
#include "format.h"
#include "mesh_file.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

void read_sphere(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"center", "center1", "radius", "material", "transform", "sample"});
  sphere sp;
  sp.sampled = r.flag(j, p, "sample");
  sp.center = r.vector3(r.required(j, p, "center"), p + "/center");
  // A moving sphere: at "center" at time 0 and "center1" at time 1, linear before and after.
  if (j.contains("center1")) sp.center1 = r.vector3(j["center1"], p + "/center1");
  sp.radius = r.number(r.required(j, p, "radius"), p + "/radius");
  if (sp.radius <= 0)
    r.fail(p + "/radius", "expected a radius > 0, got " + format_number(sp.radius));
  if (j.contains("transform")) {
    // A sphere stays a sphere under a rotation and one scale; a non-uniform scale would make an
    // ellipsoid, which needs object-space instances (docs/geometry.md).
    const std::optional<sphere> moved =
        placed(sp, read_transform(r, j["transform"], p + "/transform"));
    if (!moved)
      r.fail(
          p + "/transform",
          "a sphere can be scaled only uniformly (an ellipsoid is a group placed by an instance)");
    sp = *moved;
  }
  sp.material = r.material_named(j, p);
  s.spheres.push_back(sp);
}

// Quads, boxes and triangles, each placed by its optional transform.
void read_quad(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"Q", "u", "v", "material", "transform", "sample"});
  quad q;
  q.sampled = r.flag(j, p, "sample");
  q.Q = r.vector3(r.required(j, p, "Q"), p + "/Q");
  q.u = r.vector3(r.required(j, p, "u"), p + "/u");
  q.v = r.vector3(r.required(j, p, "v"), p + "/v");
  q = placed(q, optional_transform(r, j, p));
  if (!spans_area(q.u, q.v)) r.fail(p, "u and v are parallel (or zero): the quad has no area");
  q.material = r.material_named(j, p);
  s.quads.push_back(q);
}

void read_box(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"a", "b", "material", "transform"});
  const point3 a = r.vector3(r.required(j, p, "a"), p + "/a");
  const point3 b = r.vector3(r.required(j, p, "b"), p + "/b");
  for (int k = 0; k < 3; ++k)
    if (a[k] == b[k])
      r.fail(p + "/b/" + std::to_string(k), "the box is flat: a and b share this coordinate");
  add_box(s, a, b, r.material_named(j, p), optional_transform(r, j, p));
  // Each side as a quad file would have to read it (a dump writes them so): a side too thin or
  // too large for its normal in float has no area to hit.
  for (std::size_t k = s.quads.size() - 6; k < s.quads.size(); ++k)
    if (!spans_area(s.quads[k].u, s.quads[k].v))
      r.fail(p, "side " + std::to_string(k + 6 - s.quads.size()) +
                    " of the box has no area in float (too thin or too large)");
}

void read_triangle(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"vertices", "normals", "uv", "material", "transform"});
  const transform t = optional_transform(r, j, p);
  const auto three = [&](const std::string& key) {
    const json& v = r.required(j, p, key);
    if (!v.is_array() || v.size() != 3)
      r.fail(p + "/" + key, "expected an array of 3 points, got " + r.type_of(v));
    return std::array<vec3, 3>{r.vector3(v[0], p + "/" + key + "/0"),
                               r.vector3(v[1], p + "/" + key + "/1"),
                               r.vector3(v[2], p + "/" + key + "/2")};
  };
  triangle tri;
  tri.p = three("vertices");
  tri = placed(tri, t);
  tri.material = r.material_named(j, p);
  if (!has_area(tri.p)) r.fail(p + "/vertices", "the vertices are collinear: no area");
  if (j.contains("normals") || j.contains("uv")) {
    triangle_shading sh;
    if (j.contains("normals")) {
      sh.normal = three("normals");
      for (std::size_t k = 0; k < 3; ++k)
        if (!(glm::length(sh.normal[k]) > 0) || !std::isfinite(glm::length(sh.normal[k])))
          r.fail(p + "/normals/" + std::to_string(k), "expected a nonzero normal");
    }
    if (j.contains("uv")) {  // texture coordinates, a pair per vertex
      const json& uv = j["uv"];
      if (!uv.is_array() || uv.size() != 3)
        r.fail(p + "/uv", "expected an array of 3 [u, v] pairs, got " + r.type_of(uv));
      for (std::size_t k = 0; k < 3; ++k) {
        const std::string at = p + "/uv/" + std::to_string(k);
        if (!uv[k].is_array() || uv[k].size() != 2)
          r.fail(at, "expected [u, v], got " + r.type_of(uv[k]));
        sh.uv[k] = glm::dvec2(r.number_in(uv[k][0], at + "/0", -1e6, 1e6),
                              r.number_in(uv[k][1], at + "/1", -1e6, 1e6));
      }
      sh.has_uv = true;
    }
    // As written when nothing places the triangle (so a dump reads back unchanged); the
    // renderers normalize them.
    tri.shading = std::int32_t(s.shading.size());
    s.shading.push_back(placed(sh, t));
  }
  s.triangles.push_back(tri);
}

// A disk: {"center": [x, y, z], "normal": [x, y, z], "radius": r, "material": name}, placed by
// an optional transform as a sphere is (rotations and one scale: a disk stretched unevenly is
// an ellipse, which a group placed by an instance draws).
void read_disk(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"center", "normal", "radius", "material", "transform"});
  disk d;
  d.center = r.vector3(r.required(j, p, "center"), p + "/center");
  d.normal = r.vector3(r.required(j, p, "normal"), p + "/normal");
  if (!has_direction(d.normal)) r.fail(p + "/normal", "expected a nonzero normal");
  d.radius = r.number(r.required(j, p, "radius"), p + "/radius");
  if (!(d.radius > 0))
    r.fail(p + "/radius", "expected a radius > 0, got " + format_number(d.radius));
  if (j.contains("transform")) {
    const std::optional<disk> moved =
        placed(d, read_transform(r, j["transform"], p + "/transform"));
    if (!moved)
      r.fail(p + "/transform",
             "a disk can be scaled only uniformly (an ellipse is a group placed by an instance)");
    d = *moved;
  }
  d.material = r.material_named(j, p);
  s.disks.push_back(d);
}

// A mesh file, named relative to the scene file and in the folder its files may use, with a
// material of the scene's (or the file's own) and a placement.
void read_mesh(const scene_reader& r, const json& j, const std::string& p, scene& s) {
  r.only_fields(j, p, {"file", "material", "transform"});
  const json& f = r.required(j, p, "file");
  if (!f.is_string() || f.get<std::string>().empty())
    r.fail(p + "/file", "expected a mesh file name, got " + r.type_of(f));
  mesh_placement how;
  how.placement = optional_transform(r, j, p);
  if (j.contains("material")) how.material = r.material_named(j, p);
  const std::filesystem::path file = r.base() / f.get<std::string>();
  if (mesh_kind(file).empty())
    r.fail(p + "/file", "\"" + f.get<std::string>() + "\" is not .obj, .gltf or .glb");
  r.guard().check(file, r.file() + ": " + p + "/file", f.get<std::string>());
  load_mesh(s, file, how, r.guard());
}

// Each kind of object a scene or a group holds: its array's field, and how one element of it is
// read into the scene (read in this order).
struct object_kind {
  const char* field;
  void (*read)(const scene_reader& r, const json& j, const std::string& p, scene& s);
};
constexpr object_kind object_kinds[] = {{"spheres", read_sphere}, {"quads", read_quad},
                                        {"boxes", read_box},      {"triangles", read_triangle},
                                        {"disks", read_disk},     {"meshes", read_mesh}};

}  // namespace

std::vector<const char*> object_fields() {
  std::vector<const char*> out;
  for (const object_kind& kind : object_kinds) out.push_back(kind.field);
  return out;
}

void read_objects(const scene_reader& r, const json& root, const std::string& at, scene& s) {
  for (const object_kind& kind : object_kinds)
    read_array(r, root, at, kind.field,
               [&](const json& j, const std::string& p) { kind.read(r, j, p, s); });
}

// The objects of the scene or of a group, as their fields: spheres always (a scene file's
// required field), quads, triangles and disks where there are some.
void write_objects(json& root, const scene& s, const shape_lists& objects) {
  const auto& [sphere_list, quad_list, triangle_list, shading, disk_list] = objects;
  const auto material_name = [&](int m) { return s.materials[std::size_t(m)].name; };
  json spheres = json::array();
  for (const sphere& sp : sphere_list) {
    json j = {{"center", vec_json(sp.center)}};
    if (sp.center1) j["center1"] = vec_json(*sp.center1);
    j["radius"] = sp.radius;
    j["material"] = material_name(sp.material);
    if (sp.sampled) j["sample"] = true;
    spheres.push_back(j);
  }
  root["spheres"] = spheres;
  if (!quad_list.empty()) {
    json quads = json::array();
    for (const quad& q : quad_list) {
      json j = {{"Q", vec_json(q.Q)},
                {"u", vec_json(q.u)},
                {"v", vec_json(q.v)},
                {"material", material_name(q.material)}};
      if (q.sampled) j["sample"] = true;
      quads.push_back(j);
    }
    root["quads"] = quads;
  }
  if (!triangle_list.empty()) {
    json triangles = json::array();
    for (const triangle& t : triangle_list) {
      json j = {{"vertices", json::array({vec_json(t.p[0]), vec_json(t.p[1]), vec_json(t.p[2])})}};
      if (t.shading >= 0 && shading[std::size_t(t.shading)].has_normals()) {
        const auto& n = shading[std::size_t(t.shading)].normal;
        j["normals"] = json::array({vec_json(n[0]), vec_json(n[1]), vec_json(n[2])});
      }
      if (t.shading >= 0 && shading[std::size_t(t.shading)].has_uv) {
        json uv = json::array();
        for (const glm::dvec2& c : shading[std::size_t(t.shading)].uv)
          uv.push_back(json::array({c.x, c.y}));
        j["uv"] = uv;
      }
      j["material"] = material_name(t.material);
      triangles.push_back(j);
    }
    root["triangles"] = triangles;
  }
  if (!disk_list.empty()) {
    json disks = json::array();
    for (const disk& d : disk_list)
      disks.push_back({{"center", vec_json(d.center)},
                       {"normal", vec_json(d.normal)},
                       {"radius", d.radius},
                       {"material", material_name(d.material)}});
    root["disks"] = disks;
  }
}

}  // namespace rtvk::scene_json
