#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace rtvk {

// Where the files a scene file names may lie: its image textures, its meshes, and the files those
// meshes name in turn (an OBJ's MTL and map_Kd images, a glTF's external buffers and images). A
// render farm that accepts users' scene files must not let one read the machine's other files
// into an image (docs/farm.md), so by default they must lie in the scene file's own folder.
struct file_access {
  bool any_path = false;       // --allow-any-path: wherever they are
  std::filesystem::path root;  // --scene-root DIR: anywhere in DIR; empty: the scene's folder
};

// The folder a scene's files must lie in, resolved once (`..` and symlinks followed), and the
// test of each file against it: a file is in the folder when its own resolved path starts with
// the folder's, compared component by component (so /data/scenes2 is not in /data/scenes).
// The check and the read that follows are separate steps: a user who can change the folder's
// symlinks while rtvk reads it can still race them, which a farm prevents by not letting users
// write into a job's folder while it renders.
class path_guard {
 public:
  // Any path at all: what --allow-any-path means.
  static path_guard any();
  // Files in `folder` (or, for "", the working folder) and below.
  static path_guard within(const std::filesystem::path& folder);
  // What `access` says for a scene file in `scene_folder`.
  static path_guard of(const file_access& access, const std::filesystem::path& scene_folder);

  // Whether `file` (relative to the working folder, or absolute) lies in the folder.
  bool allows(const std::filesystem::path& file) const;
  // What a refusal says of a file: ""`as_written`" is outside FOLDER, ...".
  std::string outside(const std::string& as_written) const;
  // Throws usage_error "`where`: "`as_written`" is outside ..." unless `file` is allowed.
  void check(const std::filesystem::path& file, const std::string& where,
             const std::string& as_written) const;

 private:
  std::optional<std::filesystem::path> root_;  // resolved; none: any path
};

}  // namespace rtvk
