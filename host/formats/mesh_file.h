#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "confined_path.h"
#include "scene.h"
#include "textures.h"

namespace rtvk {

// The largest mesh file rtvk reads (a scene's objects are bounded by max_scene_objects).
inline constexpr std::uint64_t max_mesh_file_bytes = 2ull << 30;  // 2 GiB

// How a mesh is put into a scene: the material every face gets (a scene material's index), or
// -1 for the file's own materials (mapped as docs/geometry.md says), and where it goes.
struct mesh_placement {
  int material = -1;      // index into the scene's materials; -1: the file's
  transform placement{};  // applied after the file's own node transforms
  bool cameras = false;   // a glTF's cameras appended to s.cameras too (the first sets the aspect)
};

// Appends the triangles of a Wavefront OBJ (with its MTL, when it names one) or glTF 2.0 file
// (.gltf or .glb, chosen by the extension) to `s`: their vertex normals and texture coordinates
// into s.shading, the file's materials into s.materials when `how.material` is -1. Throws
// usage_error naming the file and where in it: a missing or unreadable file, indices out of
// range, non-finite positions, a buffer that points outside its data, too many triangles, a file
// it names (MTL, image, buffer) outside the folder `guard` allows (without one: the mesh's own).
void load_mesh(scene& s, const std::filesystem::path& file, const mesh_placement& how);
void load_mesh(scene& s, const std::filesystem::path& file, const mesh_placement& how,
               const path_guard& guard);

// The same from bytes already read, `kind` "obj", "gltf" or "glb"; `name` names them in messages
// and `base` is where a glTF's external buffers and an OBJ's MTL are looked for (empty: nowhere),
// confined to `base` unless `guard` says otherwise. What the fuzzers call.
void load_mesh_bytes(scene& s, const std::string& bytes, const std::string& kind,
                     const std::string& name, const std::filesystem::path& base,
                     const mesh_placement& how);
void load_mesh_bytes(scene& s, const std::string& bytes, const std::string& kind,
                     const std::string& name, const std::filesystem::path& base,
                     const mesh_placement& how, const path_guard& guard);

// The kind of mesh file a path names by its extension ("obj", "gltf", "glb"), or "" for none.
std::string mesh_kind(const std::filesystem::path& file);

// Image `index` of a glTF file, decoded as an image texture in `encoding` (what a dumped scene
// names as "FILE#images/N": sRGB for a color texture, linear for a data texture such as a
// metallicRoughnessTexture); throws usage_error naming `name`, the file and the image. The files
// the glTF names must lie where `guard` allows (the caller checks `file` itself).
std::shared_ptr<const texel_image> gltf_image(const std::filesystem::path& file, std::size_t index,
                                              const std::string& name, const path_guard& guard,
                                              texel_encoding encoding = texel_encoding::srgb);

// A scene of one mesh file, with its own materials, and a camera that frames its bounds; the
// files it names confined as `access` says (by default to the mesh file's folder).
scene mesh_scene(const std::filesystem::path& file, const file_access& access = {});

}  // namespace rtvk
