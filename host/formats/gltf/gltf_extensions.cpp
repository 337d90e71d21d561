// The glTF extensions rtvk reads, in one table: a file that requires any other is refused by
// name; one that only uses another is drawn without it, and the scene's warnings say so.
#include <algorithm>
#include <string_view>

#include "gltf_ext.h"
#include "gltf_reader.h"

namespace rtvk {
namespace {

// An extension rtvk honours, and how (docs/mesh-formats.md says more).
struct honoured_extension {
  std::string_view name;
  std::string_view how;
};
constexpr honoured_extension honoured[] = {
    {"KHR_mesh_quantization", "integer attributes (gltf_accessor.cpp)"},
    {"KHR_texture_transform", "baked into the triangles' uv and uv1 (gltf_material.cpp)"},
    {"KHR_materials_emissive_strength", "scales the material's emission"},
    // The PBR material's parameters (gltf_pbr.cpp). KHR_materials_iridescence, _anisotropy and
    // _dispersion are not among them: refused where required, listed where used.
    {"KHR_materials_ior", "pbr_material::ior"},
    {"KHR_materials_specular", "pbr_material::specular, specular_color"},
    {"KHR_materials_transmission", "pbr_material::transmission"},
    {"KHR_materials_volume", "pbr_material::thickness, attenuation_*"},
    {"KHR_materials_clearcoat", "pbr_material::clearcoat*"},
    {"KHR_materials_sheen", "pbr_material::sheen_*"},
    {"KHR_materials_unlit", "the flat kind of the base color (gltf_material.cpp)"},
    // Drawn by next-event estimation (lights/nee.h), which `auto` picks for a scene with them.
    {"KHR_lights_punctual", "scene::punctual_lights (gltf_lights.cpp)"},
};

// The table's, and those formats/gltf_ext decodes before the walk (KHR_draco_mesh_compression,
// EXT_meshopt_compression: gltfx_honours).
bool is_honoured(const std::string& name) {
  return gltfx_honours(name) ||
         std::any_of(std::begin(honoured), std::end(honoured),
                     [&](const honoured_extension& e) { return e.name == name; });
}

}  // namespace

void check_extensions(const tinygltf::Model& m, const std::string& name,
                      std::vector<std::string>& warnings) {
  for (const std::string& e : m.extensionsRequired)
    if (!is_honoured(e))
      throw usage_error(name + ": extensionsRequired: " + e + " is not one rtvk can draw");
  std::string ignored;
  for (const std::string& e : m.extensionsUsed)
    if (!is_honoured(e) && ignored.find(e) == std::string::npos)
      ignored += (ignored.empty() ? "the extensions " : ", ") + e;
  // Animations are not played: the file is drawn at rest (its nodes' own transforms).
  if (!m.animations.empty())
    ignored += (ignored.empty() ? "" : "; ") + std::to_string(m.animations.size()) +
               (m.animations.size() == 1 ? " animation" : " animations") + " (drawn at rest)";
  const std::string line = name + ": drawn without what rtvk does not read: " + ignored;
  if (!ignored.empty() && std::find(warnings.begin(), warnings.end(), line) == warnings.end())
    warnings.push_back(line);  // once, however many times the file is placed
}

}  // namespace rtvk
