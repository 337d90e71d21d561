// libFuzzer target for the mesh loaders (OBJ through tinyobjloader, glTF and .glb through
// tinygltf, and rtvk's checks of what they return). The first byte picks the format ('o', 'g' or
// anything else: .glb); the rest is the file. Any input may be rejected, but only with
// usage_error; anything else -- a crash, another exception, undefined behaviour, a read past a
// buffer -- is a bug. Every triangle accepted has finite vertices and a material that exists,
// and every camera a glTF gives (formats/gltf_ext/, as mesh_scene asks for them) a usable name and
// path. Draco and meshopt streams are decoded on the way (seeds "draco", "meshopt").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "camera_path.h"
#include "errors.h"
#include "mesh_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string kind = data[0] == 'o' ? "obj" : data[0] == 'g' ? "gltf" : "glb";
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  rtvk::scene s;
  try {
    // No folder: an OBJ's mtllib and a glTF's external buffers are not looked for.
    rtvk::mesh_placement how;
    how.cameras = true;
    rtvk::load_mesh_bytes(s, bytes, kind, "fuzz." + kind, "", how);
  } catch (const rtvk::usage_error&) {
    return 0;
  }
  for (const rtvk::triangle& t : s.triangles) {
    if (t.material < 0 || std::size_t(t.material) >= s.materials.size()) std::abort();
    for (const rtvk::point3& p : t.p)
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
    if (t.shading >= 0 && std::size_t(t.shading) >= s.shading.size()) std::abort();
  }
  for (const rtvk::named_camera& c : s.cameras) {
    if (!rtvk::valid_camera_name(c.name)) std::abort();
    try {
      rtvk::check_camera_path(c.path);
    } catch (const std::invalid_argument&) {
      std::abort();
    }
  }
  return 0;
}
