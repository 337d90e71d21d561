// The scene file's media: the second book's constant-density fog in a sphere or a box, scattered
// by an isotropic material; read and written side by side.
#include "format.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {

// /media: the book's constant_medium, a sphere ({"shape": "sphere", "center", "radius"}) or a
// box ({"shape": "box", "a", "b", "transform"}) of fog, {"density", "material"} (isotropic).
void read_media(const scene_reader& r, const json& root, scene& s) {
  read_array(r, root, "", "media", [&](const json& j, const std::string& p) {
    const json& shape = r.required(j, p, "shape");
    const std::string sh = shape.is_string() ? shape.get<std::string>() : "";
    medium m;
    if (sh == "sphere") {
      r.only_fields(j, p, {"shape", "center", "radius", "density", "material"});
      m.shape = boundary_shape::sphere;
      m.center = r.vector3(r.required(j, p, "center"), p + "/center");
      m.radius = r.number(r.required(j, p, "radius"), p + "/radius");
      if (!(m.radius > 0))
        r.fail(p + "/radius", "expected a radius > 0, got " + format_number(m.radius));
    } else if (sh == "box") {
      r.only_fields(j, p, {"shape", "a", "b", "transform", "density", "material"});
      m.shape = boundary_shape::box;
      const point3 a = r.vector3(r.required(j, p, "a"), p + "/a");
      const point3 b = r.vector3(r.required(j, p, "b"), p + "/b");
      for (int k = 0; k < 3; ++k)
        if (a[k] == b[k])
          r.fail(p + "/b/" + std::to_string(k), "the box is flat: a and b share this coordinate");
      m.lo = glm::min(a, b);
      m.hi = glm::max(a, b);
      m.placement = optional_transform(r, j, p);
    } else {
      r.fail(p + "/shape", "expected \"sphere\" or \"box\", got " +
                               (shape.is_string() ? "\"" + sh + "\"" : r.type_of(shape)));
    }
    m.density = r.number(r.required(j, p, "density"), p + "/density");
    if (!(m.density > 0))
      r.fail(p + "/density", "expected a density > 0, got " + format_number(m.density));
    m.material = r.material_named(j, p);
    if (s.materials[std::size_t(m.material)].m.type != material_type::isotropic)
      r.fail(p + "/material", "a medium scatters by an isotropic material, \"" +
                                  s.materials[std::size_t(m.material)].name + "\" is " +
                                  type_name(s.materials[std::size_t(m.material)].m.type));
    if (s.media.size() >= max_scene_media)
      r.fail(p, "more than " + std::to_string(max_scene_media) + " media");
    s.media.push_back(m);
  });
}

void write_media(const scene& s, json& root) {
  if (s.media.empty()) return;
  json media = json::array();
  for (const medium& m : s.media) {
    json j = {{"shape", shape_name(m.shape)}};
    if (m.shape == boundary_shape::sphere) {
      j["center"] = vec_json(m.center);
      j["radius"] = m.radius;
    } else {
      j["a"] = vec_json(m.lo);
      j["b"] = vec_json(m.hi);
      if (!m.placement.is_identity()) j["transform"] = {{"matrix", matrix_json(m.placement)}};
    }
    j["density"] = m.density;
    j["material"] = s.materials[std::size_t(m.material)].name;
    media.push_back(j);
  }
  root["media"] = media;
}

}  // namespace rtvk::scene_json
