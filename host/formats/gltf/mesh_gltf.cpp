// glTF 2.0 (.gltf and .glb), through Debian's tinygltf: the entry points. The reader's parts:
// gltf_files.cpp (parsing, the files a glTF names), gltf_nodes.cpp (the node tree and its
// primitives), gltf_primitive.cpp (a primitive's attributes and morph targets),
// gltf_material.cpp (materials and their textures), gltf_accessor.cpp (every accessor checked
// against its buffer before it is read), gltf_extensions.cpp (the extensions honoured).
#include "gltf_ext.h"
#include "gltf_reader.h"
#include "input_file.h"

namespace rtvk {

void load_gltf(scene& s, const std::string& bytes, bool binary, const std::string& name,
               const std::filesystem::path& base, const mesh_placement& how,
               const path_guard& guard) {
  // formats/gltf_ext: meshopt fallback buffers stood in for, Draco and meshopt streams decoded into
  // plain accessors before the walk, and the file's cameras after it.
  tinygltf::Model model = parse_gltf(gltfx_prepare(bytes, binary), binary, name, base, guard);
  check_extensions(model, name, s.warnings);
  gltfx_decompress(model, name);
  mesh_builder b(s, name, how.placement);
  gltf_walker(model, b, how).walk_scene();
  add_gltf_lights(s, model, name, how.placement);
  if (how.cameras) add_gltf_cameras(s, model, name, how.placement, true);
}

std::shared_ptr<const texel_image> gltf_image(const std::filesystem::path& file, std::size_t index,
                                              const std::string& name, const path_guard& guard,
                                              texel_encoding encoding) {
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
                            name + ": " + file.string() + "#images/" + std::to_string(index),
                            encoding);
}

}  // namespace rtvk