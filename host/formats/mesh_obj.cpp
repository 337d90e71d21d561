// Wavefront OBJ, through Debian's tinyobjloader: polygons triangulated as fans, every index
// checked against the arrays it points into, materials from the MTL the file names.
#include <algorithm>
#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "input_file.h"
#include "mesh_builder.h"
#include "mesh_file.h"

namespace rtvk {
namespace {

double unit(double x) {
  return std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0);
}

// An MTL material as one of rtvk's (docs/geometry.md): transparent (d < 1, or an illumination
// model with refraction) is glass of index Ni; metallic (Pm >= 0.5, or illum 3, reflection on) is
// metal of Kd (Pm) or Ks (illum 3), blurred by the roughness Pr; anything else is diffuse Kd.
material from_mtl(const tinyobj::material_t& m) {
  material out;
  const bool refracts =
      m.dissolve < 1 || m.illum == 4 || m.illum == 6 || m.illum == 7 || m.illum == 9;
  if (refracts) {
    out.type = material_type::dielectric;
    out.ir = m.ior > 1 && std::isfinite(m.ior) ? m.ior : 1.5;
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

// An MTL material's map_Kd as an image texture beside the OBJ (tinted by Kd, tiled as MTL
// textures are), decoded once however many materials name it; the file is named absolute, so a
// dumped scene finds it from anywhere. Returns the scene's texture index.
int diffuse_texture(mesh_builder& b, const tinyobj::material_t& m,
                    const std::filesystem::path& base, const std::string& name,
                    const path_guard& guard, std::map<std::string, int>& textures) {
  const auto known = textures.find(m.diffuse_texname);
  if (known != textures.end()) return known->second;
  if (base.empty())
    throw usage_error(name + ": material " + m.name + ": map_Kd " + m.diffuse_texname +
                      ": no folder to read it from");
  guard.check(base / m.diffuse_texname, name + ": material " + m.name + ": map_Kd",
              m.diffuse_texname);
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::absolute(base / m.diffuse_texname, ec);
  texture t;
  t.type = texture_type::image;
  t.file = (ec ? base / m.diffuse_texname : file.lexically_normal()).string();
  t.image = load_texel_image(t.file, name + ": material " + m.name + ": map_Kd");
  t.even = color(unit(m.diffuse[0]), unit(m.diffuse[1]), unit(m.diffuse[2]));
  t.wrap_u = t.wrap_v = image_wrap::repeat;
  const int index = b.add_texture(std::move(t));
  textures[m.diffuse_texname] = index;
  return index;
}

// The MTL file an OBJ names on its first mtllib line, read from `base` ("" when none).
std::string mtl_text(const std::string& obj, const std::filesystem::path& base,
                     const std::string& name, const path_guard& guard) {
  std::istringstream lines(obj);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("mtllib", 0) != 0) continue;
    std::string file = line.substr(6);
    file.erase(0, file.find_first_not_of(" \t"));
    file.erase(file.find_last_not_of(" \t\r") + 1);
    if (file.empty() || base.empty()) return "";
    const std::filesystem::path path = base / file;
    guard.check(path, name + ": mtllib", file);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
      throw usage_error(name + ": mtllib " + file + ": no such file beside the OBJ");
    return read_regular_file(path, max_mesh_file_bytes, "material library");
  }
  return "";
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

}  // namespace

void load_obj(scene& s, const std::string& text, const std::string& name,
              const std::filesystem::path& base, const mesh_placement& how,
              const path_guard& guard) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, mtl_text(text, base, name, guard), config) || !reader.Valid()) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw usage_error(name + ": " + (why.empty() ? "not a Wavefront OBJ file" : why));
  }
  mesh_builder b(s, name, how.placement);
  const tinyobj::attrib_t& a = reader.GetAttrib();
  std::vector<int> materials;  // the file's material k -> the scene's
  if (how.material < 0) {
    std::map<std::string, int> textures;  // map_Kd file -> the scene's texture
    for (const tinyobj::material_t& m : reader.GetMaterials()) {
      material out = from_mtl(m);
      if (!m.diffuse_texname.empty() && out.type != material_type::dielectric)
        out.texture = diffuse_texture(b, m, base, name, guard, textures);
      materials.push_back(b.add_material(name + ":" + m.name, out));
    }
  }
  int fallback = how.material;  // faces without a material: a gray diffuse one, made when needed
  const transform node;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const tinyobj::mesh_t& mesh = shape.mesh;
    std::size_t at = 0;
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      const std::string where = "shape \"" + shape.name + "\" face " + std::to_string(f);
      const unsigned corners = mesh.num_face_vertices[f];
      if (corners != 3) b.fail(where, "has " + std::to_string(corners) + " vertices, not 3");
      if (at + 3 > mesh.indices.size()) b.fail(where, "indices end early");
      std::array<point3, 3> p;
      std::array<vec3, 3> n;
      std::array<glm::dvec2, 3> uv{};
      bool smooth = true, has_uv = true;
      for (std::size_t k = 0; k < 3; ++k)
        read_corner(b, a, mesh.indices[at + k], where, p[k], n[k], uv[k], smooth, has_uv);
      at += 3;
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
      b.add(p, material, smooth ? std::optional(n) : std::nullopt, uv, has_uv, node);
    }
  }
}

}  // namespace rtvk
