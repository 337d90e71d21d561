#pragma once
// Internal to formats/: what the scene file's readers and writers (scene_file*.cpp) share -- the
// validator that reads a field and names it in every refusal, and each kind's reader and writer.
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "confined_path.h"
#include "scene.h"

namespace rtvk::scene_json {

using json = nlohmann::ordered_json;

// Walks a parsed document, checking each value against what the format expects. Every failure
// names the file and the JSON path (RFC 6901) of the offending value.
class scene_reader {
 public:
  scene_reader(std::string file, std::filesystem::path base, path_guard guard)
      : file_(std::move(file)), base_(std::move(base)), guard_(std::move(guard)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;
  void only_fields(const json& obj, const std::string& path,
                   const std::set<std::string>& allowed) const;
  const json& required(const json& obj, const std::string& path, const std::string& key) const;
  double number(const json& j, const std::string& path) const;
  double number_in(const json& j, const std::string& path, double lo, double hi) const;
  long long integer(const json& j, const std::string& path, long long lo, long long hi) const;
  vec3 vector3(const json& j, const std::string& path) const;
  color albedo(const json& j, const std::string& path) const;    // each channel in [0, 1]
  color radiance(const json& j, const std::string& path) const;  // each channel >= 0
  // An optional true or false field (default false).
  bool flag(const json& j, const std::string& path, const char* key) const;
  // The index of the material that j's "material" names (path: j's place in the file).
  int material_named(const json& j, const std::string& path) const;

  static std::string type_of(const json& j);
  const std::string& file() const { return file_; }
  const std::filesystem::path& base() const { return base_; }  // relative paths start here
  const path_guard& guard() const { return guard_; }

  // Each material's index in the scene, by name (filled as /materials is read).
  mutable std::map<std::string, int> material_index;
  // Images already decoded for this file, by the path read: a scene naming one image in many
  // textures holds and uploads its texels once.
  mutable std::map<std::string, std::shared_ptr<const texel_image>> images;

 private:
  std::string file_;            // named in every message
  std::filesystem::path base_;  // the scene file's folder
  path_guard guard_;            // where the files it names may lie
};

// A key as a JSON pointer's component ("~" and "/" escaped).
std::string escape_pointer(const std::string& key);

// The array field `key` of `root` (empty when absent), each element read by `read`; `at` is
// where `root` is in the file (a JSON pointer; "" for the file's root).
template <typename Read>
void read_array(const scene_reader& r, const json& root, const std::string& at,
                const std::string& key, Read read) {
  if (!root.contains(key)) return;
  const json& items = root[key];
  if (!items.is_array()) r.fail(at + "/" + key, "expected an array, got " + r.type_of(items));
  for (std::size_t i = 0; i < items.size(); ++i)
    read(items[i], at + "/" + key + "/" + std::to_string(i));
}

json vec_json(const vec3& v);

// Each part of the file has a reader (from the document's root into the scene) and a writer
// (from the scene into the root), side by side in its own file.

// scene_file_camera.cpp: "camera" or "cameras".
void read_cameras(const scene_reader& r, const json& root, scene& s);
void write_cameras(const scene& s, json& root);

// scene_file_materials.cpp: "noise_seed" and "materials" (with their textures and images).
void read_materials(const scene_reader& r, const json& root, scene& s);
void write_materials(const scene& s, json& root);
// A color field that may be a texture object instead (at `p`): sets m.albedo, or appends the
// texture to s.textures and sets m.texture; a lamp's color (`radiance`) may pass 1.
void read_color_or_texture(const scene_reader& r, const json& j, const std::string& p,
                           bool radiance, scene& s, material& m);
json texture_json(const texture& t);  // a texture object, as read_color_or_texture reads it

// scene_file_pbr.cpp: a PBR material's fields beyond the base color (`albedo`) and the surface's.
std::vector<std::string> pbr_fields();
void read_pbr(const scene_reader& r, const json& j, const std::string& p, scene& s, material& m);
void write_pbr(const scene& s, const material& m, json& j);

// scene_file_objects.cpp: "spheres", "quads", "boxes", "triangles" and "meshes", of the scene
// (at "") or of a group (at its pointer).
void read_objects(const scene_reader& r, const json& root, const std::string& at, scene& s);
void write_objects(json& root, const scene& s, const shape_lists& objects);
// The fields read_objects reads, one a kind of object: what a scene file's top level and a
// group may hold besides their own fields.
std::vector<const char*> object_fields();

// scene_file_groups.cpp: placements, "groups" and "instances".
transform read_transform(const scene_reader& r, const json& j, const std::string& p);
transform optional_transform(const scene_reader& r, const json& j, const std::string& p);
json matrix_json(const transform& t);
void read_groups(const scene_reader& r, const json& root, scene& s);
void write_groups(const scene& s, json& root);

// scene_file_media.cpp: "media".
void read_media(const scene_reader& r, const json& root, scene& s);
void write_media(const scene& s, json& root);

// scene_file_lights.cpp: "lights", the punctual lights.
void read_lights(const scene_reader& r, const json& root, scene& s);
void write_lights(const scene& s, json& root);

}  // namespace rtvk::scene_json
