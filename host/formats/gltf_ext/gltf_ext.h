#pragma once
// The glTF extensions formats/gltf_ext/ reads for the glTF loader (formats/mesh_gltf.cpp): Draco
// and meshopt compression, decoded into the plain buffers, views and accessors the loader reads,
// and the file's cameras. Every message reads "<file>: <where>: <what>" (usage_error, exit 2).
#include <string>

#include <tiny_gltf.h>

#include "scene.h"

namespace rtvk {

// A node's own transform: its matrix, or translation * rotation * scale. What the glTF reader
// places meshes and skins by, and add_gltf_cameras poses cameras by.
transform node_transform(const tinygltf::Node& n);

// Whether rtvk reads extension `ext` when a file requires it (extensionsRequired):
// KHR_draco_mesh_compression and EXT_meshopt_compression.
bool gltfx_honours(const std::string& ext);

// A glTF's bytes (.glb when `binary`) as tinygltf can parse them: each EXT_meshopt_compression
// fallback buffer that has no uri given a stand-in of 4 bytes (it holds nothing until the views
// that point into it are decoded), each KHR_draco_mesh_compression primitive's indices accessor
// (which has no view) dropped for the decoded faces. Bytes without either extension come back
// unchanged.
std::string gltfx_prepare(const std::string& bytes, bool binary);

// Decodes every EXT_meshopt_compression buffer view into a buffer of its own, then every
// KHR_draco_mesh_compression primitive into new float accessors (and 32-bit indices) that the
// primitive names instead of its own; a corrupt or inconsistent stream is refused by file, mesh
// and primitive. `name` is the file, as messages name it.
void gltfx_decompress(tinygltf::Model& m, const std::string& name);

// Appends to s.cameras one camera per node of the default scene that has one, in node order,
// posed by its world transform placed by `placement`: glTF cameras look down their -Z with +Y
// up. Named by the camera's name, else the node's, else "camera<K>", made valid and unique.
// The first sets s.render.aspect to its aspectRatio (perspective) or xmag / ymag (orthographic)
// when `first_sets_aspect`.
void add_gltf_cameras(scene& s, const tinygltf::Model& m, const std::string& name,
                      const transform& placement, bool first_sets_aspect);

}  // namespace rtvk
