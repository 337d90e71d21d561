#pragma once
// Internal to the glTF reader (formats/gltf/, part of rtvk_formats): what its sources give each
// other. load_gltf (mesh_gltf.cpp) parses the file, checks its extensions, has formats/gltf_ext
// decode its compressed data, walks its default scene, then adds its cameras.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "confined_path.h"
#include "gltf_ext.h"
#include "mesh_builder.h"
#include "mesh_file.h"

namespace rtvk {

// gltf_files.cpp: a glTF parsed (its images kept encoded, its external files read by rtvk's
// reader where `guard` allows; `base` empty: none read). Throws usage_error naming `name`.
tinygltf::Model parse_gltf(const std::string& bytes, bool binary, const std::string& name,
                           const std::filesystem::path& base, const path_guard& guard);

// gltf_extensions.cpp: refuses a file that requires an extension rtvk does not honour (naming
// `name` and the extension), and appends one line to `warnings` (unless there already) listing
// the optional ones it ignores and the animations it does not play.
void check_extensions(const tinygltf::Model& m, const std::string& name,
                      std::vector<std::string>& warnings);

// gltf_lights.cpp: appends to s.punctual_lights one light per node of the default scene whose
// KHR_lights_punctual names one, in node order, placed by its world transform after `placement`:
// a light shines down its node's -Z. Throws usage_error naming `name`, the node and the light.
void add_gltf_lights(scene& s, const tinygltf::Model& m, const std::string& name,
                     const transform& placement);

// Where a material's texture coordinates come from: the TEXCOORD_<set> attribute, mapped by
// KHR_texture_transform's matrix (in glTF's uv, v down) before rtvk flips v.
struct uv_mapping {
  int set = 0;             // which TEXCOORD_n
  glm::dmat3 matrix{1.0};  // offset * rotation * scale, applied to (u, v, 1)
};

// gltf_material.cpp: the file's materials, appended to the scene once each, with the textures
// they use; gltf_pbr.cpp: their metallic-roughness parameters and KHR_materials_* extensions.
class gltf_materials {
 public:
  gltf_materials(const tinygltf::Model& m, mesh_builder& b);
  // The scene's material for the file's material k; fails naming `where` if there is none.
  int scene_material(int k, const std::string& where) const;
  // The texture coordinates the file's material k reads (its base color texture's; else its
  // emissive texture's; else its first other texture's): a triangle's uv.
  const uv_mapping& mapping(int k) const { return mappings_[std::size_t(k)]; }
  // Its emissive texture's, where it has both textures and they read different sets or
  // transforms: a triangle's second set (triangle_shading::uv1); else none.
  const std::optional<uv_mapping>& second_mapping(int k) const {
    return second_mappings_[std::size_t(k)];
  }

 private:
  material make(const tinygltf::Material& mat, std::size_t k, const std::string& where);
  // gltf_pbr.cpp: pbrMetallicRoughness, normalTexture and the KHR_materials_* extensions.
  void read_pbr(const tinygltf::Material& mat, std::size_t k, pbr_material& p,
                const std::string& where);
  void read_extensions(const tinygltf::Material& mat, std::size_t k, pbr_material& p,
                       const std::string& where);
  // A parameter texture of material k (-1 where info names none), decoded in `encoding`; a
  // warning where it reads other texture coordinates than the triangles carry.
  int parameter_texture(const tinygltf::TextureInfo& info, texel_encoding encoding, std::size_t k,
                        const std::string& where);
  int source_of(int t, const std::string& where) const;
  std::shared_ptr<const texel_image> decoded(int source, texel_encoding encoding,
                                             const std::string& where);
  int image_texture(int t, texel_encoding encoding, const color& tint, const std::string& where);

  const tinygltf::Model& m_;
  mesh_builder& b_;
  std::vector<int> materials_;        // the file's material k -> the scene's
  std::vector<uv_mapping> mappings_;  // the file's material k's texture coordinates
  std::vector<bool> mapped_;  // mappings_[k] is a texture's (else the first texture read sets it)
  std::vector<std::optional<uv_mapping>> second_mappings_;  // and its emissive texture's
  // The file's image k decoded in one color space, shared by every texture that uses it.
  std::map<std::pair<int, texel_encoding>, std::shared_ptr<const texel_image>> images_;
};

// gltf_nodes.cpp: walks the default scene's node tree, appending each mesh's triangles.
class gltf_walker {
 public:
  gltf_walker(const tinygltf::Model& m, mesh_builder& b, const mesh_placement& how);
  void walk_scene();

 private:
  void walk(int index, const transform& parent, int depth);
  void add_mesh(const tinygltf::Node& n, const transform& t, const std::string& node);
  void add_primitive(const tinygltf::Primitive& prim, const std::vector<double>& weights,
                     const std::vector<glm::dmat4>* joints, const transform& node,
                     const std::string& where);
  // gltf_skin.cpp: skins at rest.
  glm::dmat4 global_matrix(int node, const std::string& where);
  const std::vector<glm::dmat4>& joint_matrices(int skin, const std::string& node);
  int material_of(const tinygltf::Primitive& prim, const std::string& where);
  uv_mapping mapping_of(const tinygltf::Primitive& prim) const;
  std::optional<uv_mapping> second_mapping_of(const tinygltf::Primitive& prim) const;
  // A vertex's texture coordinates, failing naming `where` unless finite and within +-1e6.
  glm::dvec2 checked_uv(glm::dvec2 uv, const std::string& where) const;

  const tinygltf::Model& m_;
  mesh_builder& b_;
  const mesh_placement& how_;
  std::optional<gltf_materials> materials_;  // the file's, unless how_ names one for all
  int fallback_ = -1;         // primitives without a material: gray diffuse, made when needed
  std::vector<bool> walked_;  // node k has been walked
  std::vector<int> parents_;  // node k's parent, or -1 (made when a skin needs it)
  std::map<int, std::vector<glm::dmat4>> skins_;  // skin k's joint matrices
};

}  // namespace rtvk
