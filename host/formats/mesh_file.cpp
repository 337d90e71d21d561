#include "mesh_file.h"

#include "mesh_tangents.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "errors.h"
#include "input_file.h"

namespace rtvk {

// mesh_obj.cpp and mesh_gltf.cpp.
void load_obj(scene& s, const std::string& text, const std::string& name,
              const std::filesystem::path& base, const mesh_placement& how,
              const path_guard& guard);
void load_gltf(scene& s, const std::string& bytes, bool binary, const std::string& name,
               const std::filesystem::path& base, const mesh_placement& how,
               const path_guard& guard);

namespace {

// The folder a mesh's own files are confined to by default: the one it is read from.
path_guard own_folder(const std::filesystem::path& base) {
  return base.empty() ? path_guard::any() : path_guard::within(base);
}

}  // namespace

std::string mesh_kind(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return "obj";
  if (ext == ".gltf") return "gltf";
  if (ext == ".glb") return "glb";
  return "";
}

void load_mesh_bytes(scene& s, const std::string& bytes, const std::string& kind,
                     const std::string& name, const std::filesystem::path& base,
                     const mesh_placement& how) {
  load_mesh_bytes(s, bytes, kind, name, base, how, own_folder(base));
}

void load_mesh_bytes(scene& s, const std::string& bytes, const std::string& kind,
                     const std::string& name, const std::filesystem::path& base,
                     const mesh_placement& how, const path_guard& guard) {
  const std::size_t before = s.triangles.size();
  if (kind == "obj")
    load_obj(s, bytes, name, base, how, guard);
  else if (kind == "gltf" || kind == "glb")
    load_gltf(s, bytes, kind == "glb", name, base, how, guard);
  else
    throw usage_error(name + ": not a mesh file (expected .obj, .gltf or .glb)");
  generate_tangents(s, before);  // for the normal-mapped faces the file gave none
}

void load_mesh(scene& s, const std::filesystem::path& file, const mesh_placement& how) {
  load_mesh(s, file, how, own_folder(file.parent_path().empty() ? "." : file.parent_path()));
}

void load_mesh(scene& s, const std::filesystem::path& file, const mesh_placement& how,
               const path_guard& guard) {
  const std::string kind = mesh_kind(file);
  if (kind.empty())
    throw usage_error(file.string() + ": not a mesh file (expected .obj, .gltf or .glb)");
  const std::string bytes = read_regular_file(file, max_mesh_file_bytes, "mesh file");
  const std::size_t before = s.triangles.size();
  load_mesh_bytes(s, bytes, kind, file.string(),
                  file.parent_path().empty() ? "." : file.parent_path(), how, guard);
  if (s.triangles.size() == before)
    throw usage_error(file.string() + ": the file has no triangles");
  s.compounds.push_back({true, std::uint32_t(before), std::uint32_t(s.triangles.size() - before)});
}

scene mesh_scene(const std::filesystem::path& file, const file_access& access) {
  scene s;
  s.name = file.string();
  s.render.transform = view_transform::standard;  // sRGB, as the model's own viewers show it
  // A picture rather than the lesson's one noisy sample: jittered (antialiased) samples, enough
  // that a textured model reads at a glance; depth enough for glass and interreflection.
  s.render.spp = 32;
  s.render.jitter = true;
  s.render.max_depth = 16;
  // A neutral sky, brighter above (0.7) than below (0.3): the lesson's blue one tints a model the
  // way no viewer of its file does, and at radiance 1 it lights the model twice as bright as the
  // Khronos sample viewer's neutral environment shows it (docs/mesh-formats.md measures both).
  s.sky = {color(0.3), color(0.7)};
  const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
  mesh_placement how;
  how.cameras = true;
  load_mesh(s, file, how, path_guard::of(access, folder));
  // A camera that frames the bounds: looking at their center from the front, a little above and
  // to the right, far enough that the bounding sphere fills the view.
  point3 lo(INFINITY), hi(-INFINITY);
  for (const triangle& t : s.triangles)
    for (const point3& p : t.p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const point3 center = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-9);
  camera_pose& c = main_camera(s).pose;
  c.vfov = 40;
  c.lookat = center;
  const double distance = 1.1 * radius / std::sin(0.5 * c.vfov * M_PI / 180);
  c.lookfrom = center + distance * glm::normalize(vec3(0.4, 0.3, 1.0));
  c.focus_dist = distance;
  // A file's own cameras (glTF) come first, the first the default; the framing one stays last.
  std::rotate(s.cameras.begin(), s.cameras.begin() + 1, s.cameras.end());
  return s;
}

}  // namespace rtvk
