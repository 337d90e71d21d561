// Wavefront OBJ, through Debian's tinyobjloader, read as viewers read it: faces of any number of
// corners cut into triangles in their plane (obj_polygon.h), every index checked against the
// arrays it points into, materials from every MTL the mtllib lines name (obj_material.h),
// their maps as sRGB image textures, vertex colors. A file it names that is missing is a
// warning and drawn gray; a file outside the allowed folder, or a non-finite number, is refused.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include <tiny_obj_loader.h>

#include "input_file.h"
#include "mesh_builder.h"
#include "mesh_file.h"
#include "obj_material.h"
#include "obj_polygon.h"

namespace rtvk {
namespace {

// A name as the OBJ or MTL writes it, with Windows' separators turned into '/' (".\tex.jpg").
std::string portable(std::string name) {
  std::replace(name.begin(), name.end(), '\\', '/');
  return name;
}

// What the OBJ's own lines say before tinyobjloader reads them: the MTL files of its mtllib
// lines (several on a line, or several lines), whether any vertex has a color, and every number
// of a `v` line checked finite (tinyobjloader would read "nan" and "1e999" on).
struct obj_lines {
  std::vector<std::string> mtllibs;  // as written, separators made portable
  bool colors = false;               // some `v` line has x y z r g b
};

obj_lines scan_lines(const std::string& text, const std::string& name) {
  obj_lines out;
  std::size_t number = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + start, end - start);
    start = end + 1;
    ++number;
    std::vector<std::string_view> fields;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
      std::size_t j = i;
      while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
      if (j > i) fields.push_back(line.substr(i, j - i));
      i = j;
    }
    if (fields.empty()) continue;
    if (fields[0] == "mtllib") {
      for (std::size_t k = 1; k < fields.size(); ++k)
        out.mtllibs.push_back(portable(std::string(fields[k])));
    } else if (fields[0] == "v") {
      out.colors = out.colors || fields.size() >= 7;
      for (std::size_t k = 1; k < fields.size() && k <= 7; ++k) {
        std::string_view f = fields[k].substr(0, 1) == "+" ? fields[k].substr(1) : fields[k];
        double x = 0;
        const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), x);
        const bool read = ptr != f.data();
        if ((read && !std::isfinite(x)) || ec == std::errc::result_out_of_range)
          throw usage_error(name + ":" + std::to_string(number) + ": v: number " +
                            std::to_string(k) + " is not finite, got '" +
                            std::string(fields[k].substr(0, 40)) + "'");
      }
    }
  }
  return out;
}

// The MTL files' text, one after another (each newmtl starts a material); a missing one is a
// warning, its materials then drawn gray.
std::string mtl_text(scene& s, const std::vector<std::string>& files,
                     const std::filesystem::path& base, const std::string& name,
                     const path_guard& guard) {
  std::string text;
  if (base.empty()) return text;
  for (const std::string& file : files) {
    const std::filesystem::path path = base / file;
    guard.check(path, name + ": mtllib", file);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
      s.warnings.push_back(name + ": mtllib " + file +
                           ": no such file beside the OBJ; its materials are drawn gray");
      continue;
    }
    text += read_regular_file(path, max_mesh_file_bytes, "material library") + "\n";
  }
  return text;
}

// The image maps of one OBJ: each file decoded once (as sRGB), each material's map a texture of
// its own (its own tint), so that two materials on one image keep their two colors.
class obj_maps {
 public:
  obj_maps(scene& s, mesh_builder& b, const std::filesystem::path& base, const path_guard& guard)
      : s_(s), b_(b), base_(base), guard_(guard) {}

  // The texture of map `kind` (map_Kd, map_Ke...) `file` of material `m`, tinted by `tint`,
  // decoded as `encoding` (colors sRGB, data linear); -1 where the file is missing (a warning).
  int texture(const std::string& m, const char* kind, const std::string& file, const color& tint,
              texel_encoding encoding = texel_encoding::srgb) {
    const std::shared_ptr<const texel_image> decoded = image(m, kind, file, encoding);
    if (!decoded) return -1;
    rtvk::texture t;
    t.type = texture_type::image;
    t.file = resolved(file).string();
    t.color_space = encoding;  // as decoded: a dump says so, and reads back alike
    t.image = decoded;
    t.even = tint;
    t.wrap_u = t.wrap_v = image_wrap::repeat;  // MTL maps tile
    return b_.add_texture(std::move(t));
  }

  std::filesystem::path resolved(const std::string& file) const {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(base_ / portable(file), ec);
    return ec ? base_ / portable(file) : p.lexically_normal();
  }

 private:
  std::shared_ptr<const texel_image> image(const std::string& m, const char* kind,
                                           const std::string& file, texel_encoding encoding) {
    const std::string what = b_.name() + ": material " + m + ": " + kind;
    if (base_.empty()) throw usage_error(what + " " + file + ": no folder to read it from");
    guard_.check(base_ / portable(file), what, file);
    const std::string path = resolved(file).string();
    const std::pair key(path, encoding);
    const auto known = images_.find(key);
    if (known != images_.end()) return known->second;
    std::error_code ec;
    std::shared_ptr<const texel_image> decoded;
    if (std::filesystem::exists(path, ec))
      decoded = load_texel_image(path, what, encoding);
    else
      s_.warnings.push_back(what + " " + file + ": no such file; drawn without it");
    images_[key] = decoded;
    return decoded;
  }

  scene& s_;
  mesh_builder& b_;
  std::filesystem::path base_;  // the OBJ's folder
  const path_guard& guard_;
  // (file, color space) -> decoded
  std::map<std::pair<std::string, texel_encoding>, std::shared_ptr<const texel_image>> images_;
};

// The maps of a material's PBR parameters (docs/mesh-formats.md's MTL table), decoded as data
// (linear) but for none: map_Pr and map_Pm are one metallic-roughness texture (green roughness,
// blue metallic, as glTF packs them) where they name one file, or where map_Pr stands alone and
// the metallic is 0 (the blue it reads as metallic is then multiplied by 0); other pairs are a
// warning. map_Ps: the sheen color's texture (a weight, gray). norm (else map_Bump or bump): the
// normal map, its -bm the normal scale, as Blender reads them.
void add_pbr_maps(scene& s, const mesh_builder& b, obj_maps& maps, const tinyobj::material_t& m,
                  pbr_material& p) {
  const texel_encoding linear = texel_encoding::linear;
  const std::string& pr = m.roughness_texname;
  const std::string& pm = m.metallic_texname;
  if (!pr.empty() && (pr == pm || (pm.empty() && p.metallic == 0)))
    p.metallic_roughness_texture = maps.texture(m.name, "map_Pr", pr, color(1), linear);
  else if (!pr.empty() || !pm.empty())
    s.warnings.push_back(b.name() + ": material " + m.name + ": " +
                         (pr.empty() ? "map_Pm " + pm : "map_Pr " + pr) +
                         ": not drawn (rtvk reads metallic and roughness from one texture, blue "
                         "and green: map_Pr and map_Pm must name one file, or map_Pr stand alone "
                         "with the metallic 0)");
  if (!m.sheen_texname.empty())
    p.sheen_color_texture = maps.texture(m.name, "map_Ps", m.sheen_texname, color(1), linear);
  const bool norm = !m.normal_texname.empty();
  const std::string& normal = norm ? m.normal_texname : m.bump_texname;
  if (!normal.empty()) {
    p.normal_texture = maps.texture(m.name, norm ? "norm" : "map_Bump", normal, color(1), linear);
    const double scale = (norm ? m.normal_texopt : m.bump_texopt).bump_multiplier;
    p.normal_scale = std::isfinite(scale) ? std::max(0.0, scale) : 1.0;
  }
}

// The scene's material for each of the file's, with its maps.
std::vector<int> add_materials(scene& s, mesh_builder& b, const tinyobj::ObjReader& reader,
                               const mtl_statements& statements, const std::filesystem::path& base,
                               const path_guard& guard) {
  std::vector<int> out;
  obj_maps maps(s, b, base, guard);
  for (const tinyobj::material_t& m : reader.GetMaterials()) {
    const auto given = statements.find(m.name);
    material mat =
        mtl_material(m, given == statements.end() ? std::set<std::string>{} : given->second);
    if (!m.diffuse_texname.empty())
      mat.texture = maps.texture(m.name, "map_Kd", m.diffuse_texname, mat.albedo);
    add_pbr_maps(s, b, maps, m, mat.pbr);
    if (!m.emissive_texname.empty()) {
      // A map_Ke without Ke glows at the map's own color (as Blender reads it).
      if (mat.emission == color(0)) mat.emission = color(1);
      mat.emission_texture = maps.texture(m.name, "map_Ke", m.emissive_texname, color(1));
    }
    if (!m.alpha_texname.empty()) {
      // The renderer reads opacity from the texture's alpha channel: a map_d that is map_Kd's
      // own file (an RGBA image) is drawn; a separate opacity image is not.
      if (mat.texture >= 0 && maps.resolved(m.alpha_texname) == maps.resolved(m.diffuse_texname))
        mat.alpha = alpha_mode::blend;
      else
        s.warnings.push_back(b.name() + ": material " + m.name + ": map_d " + m.alpha_texname +
                             ": not drawn (rtvk reads opacity from map_Kd's alpha channel)");
    }
    out.push_back(b.add_material(b.name() + ":" + m.name, mat));
  }
  return out;
}

// One corner of a face: its position, and its normal and texture coordinates where the file
// gives them (`smooth` or `has_uv` cleared where it does not); every index checked.
void read_corner(const mesh_builder& b, const tinyobj::attrib_t& a, const tinyobj::index_t& i,
                 const std::string& where, point3& p, vec3& n, glm::dvec2& uv, bool& smooth,
                 bool& has_uv) {
  const std::size_t positions = a.vertices.size() / 3, normals = a.normals.size() / 3,
                    uvs = a.texcoords.size() / 2;
  if (i.vertex_index < 0 || std::size_t(i.vertex_index) >= positions)
    b.fail(where, "vertex index " + std::to_string(i.vertex_index + 1) + " is not one of the " +
                      std::to_string(positions) + " positions");
  const std::size_t v = std::size_t(i.vertex_index);
  p = b.position(vec3(a.vertices[3 * v], a.vertices[3 * v + 1], a.vertices[3 * v + 2]), transform{},
                 where);
  if (i.normal_index >= 0 && std::size_t(i.normal_index) < normals) {
    const std::size_t m = std::size_t(i.normal_index);
    n = vec3(a.normals[3 * m], a.normals[3 * m + 1], a.normals[3 * m + 2]);
  } else if (i.normal_index >= 0) {
    b.fail(where, "normal index " + std::to_string(i.normal_index + 1) + " is not one of the " +
                      std::to_string(normals) + " normals");
  } else {
    smooth = false;
  }
  if (i.texcoord_index >= 0 && std::size_t(i.texcoord_index) < uvs) {
    const std::size_t t = std::size_t(i.texcoord_index);
    uv = glm::dvec2(a.texcoords[2 * t], a.texcoords[2 * t + 1]);
    if (!(std::abs(uv.x) <= 1e6 && std::abs(uv.y) <= 1e6))
      b.fail(where,
             "texture coordinate " + std::to_string(t + 1) + " is not finite or beyond +-1e6");
  } else if (i.texcoord_index >= 0) {
    b.fail(where, "texture coordinate index " + std::to_string(i.texcoord_index + 1) +
                      " is not one of the " + std::to_string(uvs) + " coordinates");
  } else {
    has_uv = false;
  }
}

// A vertex's color (tinyobjloader's, 1 where a `v` line has none), alpha 1.
glm::vec4 vertex_color(const tinyobj::attrib_t& a, const tinyobj::index_t& i) {
  const std::size_t v = std::size_t(i.vertex_index);
  if (3 * v + 2 >= a.colors.size()) return glm::vec4(1);
  return glm::vec4(float(a.colors[3 * v]), float(a.colors[3 * v + 1]), float(a.colors[3 * v + 2]),
                   1.0f);
}

// One face of the file, cut into triangles.
struct obj_face {
  std::vector<point3> p;
  std::vector<vec3> n;
  std::vector<glm::dvec2> uv;
  std::vector<glm::vec4> color;
  bool smooth = true, has_uv = true;
};

void add_face(mesh_builder& b, const obj_face& f, int material, bool colors) {
  const transform node;
  for (const std::array<std::size_t, 3>& t : triangulate_polygon(f.p)) {
    const std::array<point3, 3> p{f.p[t[0]], f.p[t[1]], f.p[t[2]]};
    const std::array<vec3, 3> n{f.n[t[0]], f.n[t[1]], f.n[t[2]]};
    const std::array<glm::dvec2, 3> uv{f.uv[t[0]], f.uv[t[1]], f.uv[t[2]]};
    std::optional<std::array<glm::vec4, 3>> c;
    if (colors) c = std::array<glm::vec4, 3>{f.color[t[0]], f.color[t[1]], f.color[t[2]]};
    b.add(p, material, f.smooth ? std::optional(n) : std::nullopt, uv, f.has_uv, node, c);
  }
}

}  // namespace

void load_obj(scene& s, const std::string& text, const std::string& name,
              const std::filesystem::path& base, const mesh_placement& how,
              const path_guard& guard) {
  const obj_lines lines = scan_lines(text, name);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // obj_polygon.h cuts faces in their plane
  config.vertex_color = lines.colors;
  tinyobj::ObjReader reader;
  const std::string mtl = mtl_text(s, lines.mtllibs, base, name, guard);
  if (!reader.ParseFromString(text, mtl, config) || !reader.Valid()) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw usage_error(name + ": " + (why.empty() ? "not a Wavefront OBJ file" : why));
  }
  mesh_builder b(s, name, how.placement);
  const tinyobj::attrib_t& a = reader.GetAttrib();
  // The file's material k -> the scene's.
  const std::vector<int> materials =
      how.material < 0 ? add_materials(s, b, reader, statements_of(mtl), base, guard)
                       : std::vector<int>{};
  int fallback = how.material;  // faces without a material: a gray diffuse one, made when needed
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const tinyobj::mesh_t& mesh = shape.mesh;
    std::size_t at = 0;
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      const std::string where = "shape \"" + shape.name + "\" face " + std::to_string(f);
      const std::size_t corners = mesh.num_face_vertices[f];
      if (at + corners > mesh.indices.size()) b.fail(where, "indices end early");
      obj_face face;
      face.p.resize(corners);
      face.n.resize(corners);
      face.uv.resize(corners);
      for (std::size_t k = 0; k < corners; ++k) {
        const tinyobj::index_t& i = mesh.indices[at + k];
        read_corner(b, a, i, where, face.p[k], face.n[k], face.uv[k], face.smooth, face.has_uv);
        face.color.push_back(vertex_color(a, i));
      }
      at += corners;
      int material = how.material;
      if (material < 0) {
        const int id = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
        if (id >= 0 && std::size_t(id) < materials.size()) {
          material = materials[std::size_t(id)];
        } else {
          if (fallback < 0)
            fallback =
                b.add_material(name + ":default", {material_type::lambertian, color(0.7), 0, 1.5});
          material = fallback;
        }
      }
      add_face(b, face, material, lines.colors);
    }
  }
}

}  // namespace rtvk
