// What tinygltf must not see of the compression extensions, taken out of a glTF's JSON before it
// parses the file: a meshopt fallback buffer without data (gltf_meshopt.cpp) and a Draco
// primitive's indices accessor, which has no buffer view (tinygltf refuses indices without one;
// the decoded faces stand in for it, gltf_draco.cpp).
#include <cstring>

#include "gltf_ext.h"
#include "gltf_views.h"

namespace rtvk {
namespace {

void drop_draco_indices(nlohmann::json& doc) {
  const auto meshes = doc.find("meshes");
  if (meshes == doc.end() || !meshes->is_array()) return;
  for (nlohmann::json& mesh : *meshes) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
      continue;
    for (nlohmann::json& prim : mesh["primitives"])
      if (prim.is_object() && prim.contains("extensions") && prim["extensions"].is_object() &&
          prim["extensions"].contains("KHR_draco_mesh_compression"))
        prim.erase("indices");
  }
}

std::string edited(const std::string& json) {
  nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return json;  // tinygltf says what is wrong
  stand_in_fallbacks(doc);
  drop_draco_indices(doc);
  return doc.dump();
}

std::uint32_t le32(const std::string& s, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}
void put_le32(std::string& s, std::size_t at, std::uint32_t v) {
  std::memcpy(s.data() + at, &v, 4);
}

}  // namespace

std::string gltfx_prepare(const std::string& bytes, bool binary) {
  if (bytes.find("EXT_meshopt_compression") == std::string::npos &&
      bytes.find("KHR_draco_mesh_compression") == std::string::npos)
    return bytes;
  if (!binary) return edited(bytes);
  // .glb: a 12-byte header (magic, version, length), then the JSON chunk (length, type, text).
  if (bytes.size() < 20 || le32(bytes, 16) != 0x4E4F534Au) return bytes;
  const std::uint64_t json_length = le32(bytes, 12);
  if (json_length > bytes.size() - 20) return bytes;
  std::string json = edited(bytes.substr(20, json_length));
  json.append((4 - json.size() % 4) % 4, ' ');  // chunks stay 4-byte aligned
  std::string out = bytes.substr(0, 20) + json + bytes.substr(20 + json_length);
  put_le32(out, 8, std::uint32_t(out.size()));
  put_le32(out, 12, std::uint32_t(json.size()));
  return out;
}

}  // namespace rtvk
