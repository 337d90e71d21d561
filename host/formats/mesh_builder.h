#pragma once
#include <algorithm>
#include <optional>
#include <string>

#include "errors.h"
#include "format.h"
#include "scene.h"

namespace rtvk {

// `bytes` as UTF-8: valid sequences kept, every other byte read as Latin-1 (0xE9 -> U+00E9, "é"),
// which is what an OBJ exported on Windows holds. Scene files (JSON) can only hold UTF-8, so a
// name that is not would make `rtvk scene dump` fail; read this way it dumps and reads back.
inline std::string utf8_name(const std::string& bytes) {
  std::string out;
  for (std::size_t i = 0; i < bytes.size();) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    const unsigned char c = b(i);
    // The length of a well-formed sequence starting here (RFC 3629), 0 for none.
    std::size_t n = c < 0x80                   ? 1
                    : (c >= 0xC2 && c <= 0xDF) ? 2
                    : (c >= 0xE0 && c <= 0xEF) ? 3
                    : (c >= 0xF0 && c <= 0xF4) ? 4
                                               : 0;
    for (std::size_t k = 1; k < n; ++k)
      if (i + k >= bytes.size() || (b(i + k) & 0xC0) != 0x80) n = 0;
    if (n == 3 && ((c == 0xE0 && b(i + 1) < 0xA0) || (c == 0xED && b(i + 1) > 0x9F))) n = 0;
    if (n == 4 && ((c == 0xF0 && b(i + 1) < 0x90) || (c == 0xF4 && b(i + 1) > 0x8F))) n = 0;
    if (n > 0) {
      out.append(bytes, i, n);
      i += n;
    } else {
      out += char(0xC0 | (c >> 6));
      out += char(0x80 | (c & 0x3F));
      ++i;
    }
  }
  return out;
}

// Appends one mesh file's faces to a scene, checking each as it comes: what both loaders
// (mesh_obj.cpp, mesh_gltf.cpp) share. Messages read "<file>: <where>: <what>".
class mesh_builder {
 public:
  mesh_builder(scene& s, std::string name, const transform& placement)
      : s_(s), name_(std::move(name)), placement_(placement) {}

  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw usage_error(name_ + ": " + where + ": " + what);
  }

  // One line in the scene's warnings naming the file, once however many times it is placed.
  void warn(const std::string& what) {
    const std::string line = name_ + ": " + what;
    if (std::find(s_.warnings.begin(), s_.warnings.end(), line) == s_.warnings.end())
      s_.warnings.push_back(line);
  }

  // A position of the file, checked finite and placed.
  point3 position(const vec3& p, const transform& node, const std::string& where) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail(where, "position is not finite (" + format_number(p.x) + ", " + format_number(p.y) +
                      ", " + format_number(p.z) + ")");
    const point3 q = placement_.apply_point(node.apply_point(p));
    if (!(glm::length(q) < max_scene_coordinate))
      fail(where, "position is beyond +-1e18 once placed");
    return q;
  }

  // One face; `normals` are the file's (not yet placed), or none for a flat face; `colors` its
  // corners' vertex colors (linear RGBA), or none; `uv1` its second texture coordinates (the
  // emission texture's, triangle_shading::uv1), or none; `tangents` the file's vertex tangents
  // (glTF's TANGENT, not yet placed; kept only with normals and uv), or none.
  void add(const std::array<point3, 3>& p, int material,
           const std::optional<std::array<vec3, 3>>& normals, const std::array<glm::dvec2, 3>& uv,
           bool has_uv, const transform& node,
           const std::optional<std::array<glm::vec4, 3>>& colors = std::nullopt,
           const std::optional<std::array<glm::dvec2, 3>>& uv1 = std::nullopt,
           const std::optional<std::array<glm::vec4, 3>>& tangents = std::nullopt) {
    if (object_count(s_) >= max_scene_objects)
      fail("faces", "more than " + std::to_string(max_scene_objects) + " objects in one scene");
    triangle t;
    t.p = p;
    t.material = material;
    if (!has_area(p)) return;  // no surface: nothing to hit, and no normal to shade it with
    // A mirroring placement turns counter-clockwise into clockwise: the winding is put back, so
    // that the front stays where the vertex normals point.
    const bool mirrored = compose(placement_, node).determinant() < 0;
    bool smooth = false;
    triangle_shading sh;
    if (normals) {
      smooth = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const vec3 n = (*normals)[k];
        if (!(glm::length(n) > 0) || !std::isfinite(glm::length(n))) {
          smooth = false;  // a zero or broken normal: the face is shaded flat
          break;
        }
        sh.normal[k] = placement_.apply_normal(node.apply_normal(n));
      }
      if (!smooth) sh.normal = {};
    }
    if (smooth && has_uv && tangents) add_tangents(sh, *tangents, node, mirrored);
    if (mirrored) {
      std::swap(t.p[1], t.p[2]);
      std::swap(sh.normal[1], sh.normal[2]);
      std::swap(sh.tangent[1], sh.tangent[2]);
    }
    std::array<glm::dvec2, 3> corners = uv;
    if (mirrored) std::swap(corners[1], corners[2]);
    if (colors) {
      sh.color = *colors;
      sh.has_color = true;
      if (mirrored) std::swap(sh.color[1], sh.color[2]);
    }
    if (uv1) {
      sh.uv1 = *uv1;
      sh.has_uv1 = true;
      if (mirrored) std::swap(sh.uv1[1], sh.uv1[2]);
    }
    if (smooth || has_uv || colors || uv1) {
      sh.uv = corners;
      sh.has_uv = has_uv;
      t.shading = std::int32_t(s_.shading.size());
      s_.shading.push_back(sh);
    }
    s_.triangles.push_back(t);
  }

  // The file's tangents placed into sh: directions in the surface, carried by the placement's
  // linear part (not the normals' inverse transpose); a mirroring placement flips the
  // handedness with the frame. A zero or broken one leaves the face without (then generated).
  void add_tangents(triangle_shading& sh, const std::array<glm::vec4, 3>& tangents,
                    const transform& node, bool mirrored) const {
    for (std::size_t k = 0; k < 3; ++k) {
      const vec3 t = placement_.apply_vector(node.apply_vector(vec3(tangents[k])));
      const double len = glm::length(t);
      if (!(len > 0) || !std::isfinite(len)) return;
      const float w = (tangents[k].w < 0) != mirrored ? -1.0f : 1.0f;
      sh.tangent[k] = glm::vec4(glm::vec3(t / len), w);
    }
    sh.has_tangent = true;
  }

  // A material of the file's, appended to the scene under a name no other material has (a file
  // may repeat names, or be placed twice), made UTF-8 (utf8_name); returns its index.
  int add_material(const std::string& file_name, const material& m) {
    const std::string name = utf8_name(file_name);
    std::string unique = name;
    for (int k = 2; std::any_of(s_.materials.begin(), s_.materials.end(),
                                [&](const named_material& n) { return n.name == unique; });
         ++k)
      unique = name + "#" + std::to_string(k);
    s_.materials.push_back({unique, m});
    return int(s_.materials.size() - 1);
  }

  // A texture of the file's (a glTF's base color image); returns its index.
  int add_texture(texture t) {
    s_.textures.push_back(std::move(t));
    return int(s_.textures.size() - 1);
  }

  const std::string& name() const { return name_; }

 private:
  scene& s_;
  std::string name_;     // the file, as messages name it
  transform placement_;  // the scene's placement of the mesh
};

}  // namespace rtvk
