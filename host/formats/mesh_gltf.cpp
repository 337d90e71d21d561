// glTF 2.0 (.gltf and .glb), through Debian's tinygltf: the default scene's node tree with each
// node's transform, triangle primitives with their positions, normals, first texture
// coordinates and materials. Every accessor is checked against its buffer before it is read.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_accessor.h"
#include "gltf_ext.h"
#include "input_file.h"
#include "mesh_builder.h"
#include "mesh_file.h"

namespace rtvk {
namespace {

// Images are kept as their encoded bytes: rtvk decodes the ones a material's base color uses,
// with its own limits (textures.h's decode_texel_image), when the material is made.
bool keep_image_undecoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                          const unsigned char* bytes, int size, void*) {
  if (image && bytes && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// The files a glTF names (its external buffers and images) are read through rtvk's own reader:
// regular files only, at most max_mesh_file_bytes, paths taken as written (tinygltf's default
// expands them as a shell would), and only where the guard allows. No guard (the user data)
// means the bytes came without a folder to look in: then no file is read at all.
struct gltf_files {
  const path_guard* guard = nullptr;  // where its files may lie; null: nowhere
  std::string refused;                // the first file refused by the guard, as tinygltf named it
};
bool file_exists(const std::string& path, void* user) {
  const auto* files = static_cast<const gltf_files*>(user);
  if (!files || !files->guard) return false;
  // A file outside the folder "exists", so that reading it is refused with its reason (and
  // whether such a file exists is not told).
  std::error_code ec;
  return !files->guard->allows(path) || std::filesystem::is_regular_file(path, ec);
}
std::string path_as_written(const std::string& path, void*) {
  return path;
}
bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto* files = static_cast<gltf_files*>(user);
  if (!files || !files->guard) {
    if (err) *err += "external file " + path + " not read ";
    return false;
  }
  if (!files->guard->allows(path)) {
    if (files->refused.empty()) files->refused = path;
    if (err) *err += files->guard->outside(path) + " ";
    return false;
  }
  try {
    const std::string bytes = read_regular_file(path, max_mesh_file_bytes, "glTF buffer");
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const usage_error& e) {
    if (err) *err += std::string(e.what()) + " ";
    return false;
  }
}
bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

double number_or(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.IsObject() || !v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}

double unit(double x) {
  return std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0);
}

// A glTF material as one of rtvk's (docs/geometry.md): an emissive factor that is not black is a
// lamp of that color (times KHR_materials_emissive_strength); else KHR_materials_transmission's
// factor >= 0.5 is glass of KHR_materials_ior's index (1.5 by default); else metallicFactor >=
// 0.5 is metal of the base color, blurred by the roughness; else diffuse of the base color. A
// base color texture (`base_texture`, the scene's texture index, or -1; the factor tints it)
// stands in for the base color.
material from_gltf(const tinygltf::Material& m, int base_texture) {
  material out;
  const auto ext = [&](const char* name) {
    const auto it = m.extensions.find(name);
    return it == m.extensions.end() ? tinygltf::Value() : it->second;
  };
  color emit(0);
  for (std::size_t k = 0; k < 3 && k < m.emissiveFactor.size(); ++k)
    emit[int(k)] = unit(m.emissiveFactor[k]);
  // An emissive texture marks the parts of a surface that glow (a lamp's dial, a screen); rtvk's
  // lamps emit everywhere and reflect nothing, so such a material stays what its base color makes
  // it rather than turning wholly into a lamp.
  if (emit != color(0) && m.emissiveTexture.index < 0) {
    const double strength =
        number_or(ext("KHR_materials_emissive_strength"), "emissiveStrength", 1);
    out.type = material_type::diffuse_light;
    out.albedo =
        emit * (strength >= 0 && std::isfinite(strength) && strength < 1e6 ? strength : 1.0);
    return out;
  }
  if (number_or(ext("KHR_materials_transmission"), "transmissionFactor", 0) >= 0.5) {
    out.type = material_type::dielectric;
    const double ior = number_or(ext("KHR_materials_ior"), "ior", 1.5);
    out.ir = ior > 0 && std::isfinite(ior) ? ior : 1.5;
    return out;
  }
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  color base(1);
  for (std::size_t k = 0; k < 3 && k < pbr.baseColorFactor.size(); ++k)
    base[int(k)] = unit(pbr.baseColorFactor[k]);
  out.albedo = base;
  out.texture = base_texture;
  if (pbr.metallicFactor >= 0.5) {
    out.type = material_type::metal;
    out.fuzz = unit(pbr.roughnessFactor);
    return out;
  }
  out.type = material_type::lambertian;
  return out;
}

// A glTF sampler's wrap mode as an image texture's.
image_wrap wrap_of(int gl_wrap) {
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return image_wrap::clamp;
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return image_wrap::mirror;
  return image_wrap::repeat;
}

// A node's own transform: its matrix, or translation * rotation * scale.
transform node_transform(const tinygltf::Node& n) {
  transform t;
  if (n.matrix.size() == 16) {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) t.linear[c][r] = n.matrix[std::size_t(4 * c + r)];
    t.offset = vec3(n.matrix[12], n.matrix[13], n.matrix[14]);
    return t;
  }
  glm::dmat3 scale(1.0), rotation(1.0);
  if (n.scale.size() == 3) scale = glm::dmat3(n.scale[0], 0, 0, 0, n.scale[1], 0, 0, 0, n.scale[2]);
  if (n.rotation.size() == 4)  // x, y, z, w
    rotation =
        glm::mat3_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
  t.linear = rotation * scale;
  if (n.translation.size() == 3)
    t.offset = vec3(n.translation[0], n.translation[1], n.translation[2]);
  return t;
}

class gltf_walker {
 public:
  gltf_walker(const tinygltf::Model& m, mesh_builder& b, const mesh_placement& how)
      : m_(m), b_(b), how_(how) {
    if (how.material < 0)
      for (const tinygltf::Material& mat : m.materials)
        materials_.push_back(b.add_material(
            b.name() + ":" + (mat.name.empty() ? std::to_string(materials_.size()) : mat.name),
            from_gltf(mat, base_texture(mat))));
  }

  // The scene's texture for a material's base color image (decoded once per image), or -1.
  int base_texture(const tinygltf::Material& mat) {
    const int t = mat.pbrMetallicRoughness.baseColorTexture.index;
    if (t < 0) return -1;
    const std::string where = "materials \"" + mat.name + "\" baseColorTexture";
    if (std::size_t(t) >= m_.textures.size())
      b_.fail(where, "texture " + std::to_string(t) + " does not exist");
    if (mat.pbrMetallicRoughness.baseColorTexture.texCoord != 0)
      b_.fail(where, "reads TEXCOORD_" +
                         std::to_string(mat.pbrMetallicRoughness.baseColorTexture.texCoord) +
                         " (rtvk reads TEXCOORD_0 only)");
    const int source = m_.textures[std::size_t(t)].source;
    if (source < 0 || std::size_t(source) >= m_.images.size())
      b_.fail(where, "texture " + std::to_string(t) + " has no image");
    const auto cached = image_textures_.find(source);
    if (cached != image_textures_.end()) return cached->second;
    const tinygltf::Image& img = m_.images[std::size_t(source)];
    if (img.image.empty()) b_.fail(where, "image " + std::to_string(source) + " has no data");
    texture tex;
    tex.type = texture_type::image;
    // Absolute, so that a dumped scene finds the file from wherever it is read.
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::absolute(b_.name(), ec);
    tex.file =
        (ec ? b_.name() : file.lexically_normal().string()) + "#images/" + std::to_string(source);
    const std::vector<double>& f = mat.pbrMetallicRoughness.baseColorFactor;
    for (std::size_t k = 0; k < 3 && k < f.size(); ++k) tex.even[int(k)] = unit(f[k]);
    const int sampler = m_.textures[std::size_t(t)].sampler;
    if (sampler >= 0 && std::size_t(sampler) < m_.samplers.size()) {
      tex.wrap_u = wrap_of(m_.samplers[std::size_t(sampler)].wrapS);
      tex.wrap_v = wrap_of(m_.samplers[std::size_t(sampler)].wrapT);
    } else {
      tex.wrap_u = tex.wrap_v = image_wrap::repeat;  // glTF's default sampler
    }
    tex.image = decode_texel_image(std::string(img.image.begin(), img.image.end()),
                                   b_.name() + ": images/" + std::to_string(source));
    const int index = b_.add_texture(std::move(tex));
    image_textures_[source] = index;
    return index;
  }

  void walk_scene() {
    std::vector<int> roots;
    const int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
    if (std::size_t(scene) < m_.scenes.size()) {
      roots = m_.scenes[std::size_t(scene)].nodes;
    } else {  // no scenes: every node that is nobody's child
      std::vector<bool> child(m_.nodes.size());
      for (const tinygltf::Node& n : m_.nodes)
        for (int c : n.children)
          if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
      for (std::size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(int(i));
    }
    for (int n : roots) walk(n, transform{}, 0);
  }

 private:
  void walk(int index, const transform& parent, int depth) {
    const std::string where = "node " + std::to_string(index);
    if (index < 0 || std::size_t(index) >= m_.nodes.size()) b_.fail(where, "does not exist");
    if (depth > 64) b_.fail(where, "the node tree is deeper than 64 levels (or has a cycle)");
    // glTF's nodes form trees: a node reached twice (a shared child, a cycle) would be walked
    // once per path, exponentially many times.
    if (walked_.empty()) walked_.resize(m_.nodes.size());
    if (walked_[std::size_t(index)]) b_.fail(where, "is reached twice (glTF nodes form trees)");
    walked_[std::size_t(index)] = true;
    const tinygltf::Node& n = m_.nodes[std::size_t(index)];
    const transform t = compose(parent, node_transform(n));
    if (n.mesh >= 0) {
      if (const std::optional<std::string> why = degenerate(t))
        b_.fail(where, "its transform cannot place a mesh: " + *why);
      add_mesh(n.mesh, t, where);
    }
    for (int c : n.children) walk(c, t, depth + 1);
  }

  void add_mesh(int index, const transform& t, const std::string& node) {
    if (std::size_t(index) >= m_.meshes.size())
      b_.fail(node, "mesh " + std::to_string(index) + " does not exist");
    const tinygltf::Mesh& mesh = m_.meshes[std::size_t(index)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const std::string where = "mesh " + std::to_string(index) + " primitive " + std::to_string(p);
      add_primitive(mesh.primitives[p], t, where);
    }
  }

  std::optional<accessor_reader> attribute(const tinygltf::Primitive& prim, const char* name,
                                           const std::string& where) const {
    const auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) return std::nullopt;
    return accessor_reader(m_, it->second, b_, where + " " + name);
  }

  void add_primitive(const tinygltf::Primitive& prim, const transform& t,
                     const std::string& where) {
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
      b_.fail(where, "mode " + std::to_string(prim.mode) + " is not triangles (4)");
    const std::optional<accessor_reader> pos = attribute(prim, "POSITION", where);
    if (!pos) b_.fail(where, "has no POSITION");
    if (pos->type() != TINYGLTF_TYPE_VEC3) b_.fail(where + " POSITION", "is not VEC3");
    std::optional<accessor_reader> nrm = attribute(prim, "NORMAL", where);
    if (nrm && (nrm->type() != TINYGLTF_TYPE_VEC3 || nrm->count() != pos->count()))
      b_.fail(where + " NORMAL", "is not one VEC3 per position");
    std::optional<accessor_reader> tex = attribute(prim, "TEXCOORD_0", where);
    if (tex && (tex->type() != TINYGLTF_TYPE_VEC2 || tex->count() != pos->count()))
      b_.fail(where + " TEXCOORD_0", "is not one VEC2 per position");
    std::optional<accessor_reader> idx;
    if (prim.indices >= 0) idx.emplace(m_, prim.indices, b_, where + " indices");
    const std::size_t corners = idx ? idx->count() : pos->count();
    if (corners % 3 != 0)
      b_.fail(where, std::to_string(corners) + " vertices are not whole triangles");
    const int material = material_of(prim, where);
    for (std::size_t f = 0; f < corners / 3; ++f) {
      const std::string face = where + " triangle " + std::to_string(f);
      std::array<point3, 3> p;
      std::array<vec3, 3> n;
      std::array<glm::dvec2, 3> uv{};
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint64_t v = idx ? idx->index(3 * f + k) : 3 * f + k;
        if (v >= pos->count())
          b_.fail(face, "index " + std::to_string(v) + " is not one of the " +
                            std::to_string(pos->count()) + " vertices");
        p[k] = b_.position(pos->vec(std::size_t(v)), t, face);
        if (nrm) n[k] = nrm->vec(std::size_t(v));
        // glTF's v runs down the image from its top; rtvk's (the book's, OBJ's) up from its
        // bottom.
        if (tex) {
          uv[k] = glm::dvec2(tex->get(std::size_t(v), 0), 1 - tex->get(std::size_t(v), 1));
          if (!(std::abs(uv[k].x) <= 1e6 && std::abs(uv[k].y) <= 1e6))
            b_.fail(face + " TEXCOORD_0", "is not finite or beyond +-1e6");
        }
      }
      b_.add(p, material, nrm ? std::optional(n) : std::nullopt, uv, tex.has_value(), t);
    }
  }

  int material_of(const tinygltf::Primitive& prim, const std::string& where) {
    if (how_.material >= 0) return how_.material;
    if (prim.material >= 0) {
      if (std::size_t(prim.material) >= materials_.size())
        b_.fail(where, "material " + std::to_string(prim.material) + " does not exist");
      return materials_[std::size_t(prim.material)];
    }
    if (fallback_ < 0)
      fallback_ =
          b_.add_material(b_.name() + ":default", {material_type::lambertian, color(0.7), 0, 1.5});
    return fallback_;
  }

  const tinygltf::Model& m_;
  mesh_builder& b_;
  const mesh_placement& how_;
  std::vector<int> materials_;         // the file's material k -> the scene's
  std::map<int, int> image_textures_;  // the file's image k -> the scene's texture
  int fallback_ = -1;         // primitives without a material: gray diffuse, made when needed
  std::vector<bool> walked_;  // node k has been walked
};

}  // namespace

namespace {

// Parses a glTF (its images kept encoded, its external files read by rtvk's reader where `guard`
// allows). A file outside that folder is refused by name, even where tinygltf would only warn
// (an image it could not read).
tinygltf::Model parse_gltf(const std::string& bytes, bool binary, const std::string& name,
                           const std::filesystem::path& base, const path_guard& guard) {
  if (bytes.size() > 0xffffffffu) throw usage_error(name + ": larger than 4 GiB");
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_undecoded, nullptr);
  gltf_files files{base.empty() ? nullptr : &guard, {}};
  loader.SetFsCallbacks({file_exists, path_as_written, read_whole_file, write_nothing, &files});
  tinygltf::Model model;
  std::string err, warn;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           unsigned(bytes.size()), base.string())
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                          base.string());
  if (!files.refused.empty()) throw usage_error(name + ": " + guard.outside(files.refused));
  if (!ok) {
    std::replace(err.begin(), err.end(), '\n', ' ');
    while (!err.empty() && err.back() == ' ') err.pop_back();
    throw usage_error(name + ": " + (err.empty() ? "not a glTF 2.0 file" : err));
  }
  return model;
}

}  // namespace

void load_gltf(scene& s, const std::string& bytes, bool binary, const std::string& name,
               const std::filesystem::path& base, const mesh_placement& how,
               const path_guard& guard) {
  // formats/gltf_ext: meshopt fallback buffers stood in for, Draco and meshopt streams decoded into
  // plain accessors before the walk, and the file's cameras after it.
  tinygltf::Model model = parse_gltf(gltfx_prepare(bytes, binary), binary, name, base, guard);
  gltfx_decompress(model, name);
  mesh_builder b(s, name, how.placement);
  gltf_walker(model, b, how).walk_scene();
  if (how.cameras) add_gltf_cameras(s, model, name, how.placement, true);
}

std::shared_ptr<const texel_image> gltf_image(const std::filesystem::path& file, std::size_t index,
                                              const std::string& name, const path_guard& guard) {
  const std::string kind = mesh_kind(file);
  if (kind != "gltf" && kind != "glb")
    throw usage_error(name + ": " + file.string() + " is not .gltf or .glb");
  const std::string bytes =
      read_regular_file(file, max_mesh_file_bytes, "glTF file (" + name + ")");
  const std::filesystem::path base = file.parent_path();
  const tinygltf::Model model = parse_gltf(gltfx_prepare(bytes, kind == "glb"), kind == "glb",
                                           file.string(), base.empty() ? "." : base, guard);
  if (index >= model.images.size() || model.images[index].image.empty())
    throw usage_error(name + ": " + file.string() + " has no image " + std::to_string(index));
  const std::vector<unsigned char>& img = model.images[index].image;
  return decode_texel_image(std::string(img.begin(), img.end()),
                            name + ": " + file.string() + "#images/" + std::to_string(index));
}

}  // namespace rtvk
