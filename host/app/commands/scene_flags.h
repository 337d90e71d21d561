#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "confined_path.h"
#include "scene_overrides.h"

namespace rtvk {

// Where the files a scene file names may lie (--allow-any-path, --scene-root DIR): a flag pair
// of every command that reads scene files (render, bench, view, scene dump).
class scene_path_flags {
 public:
  void add_to(CLI::App& cmd);

  // What the flags allow; throws usage_error for a --scene-root that is not a folder.
  file_access access() const;

 private:
  bool any_path_ = false;  // --allow-any-path
  std::string root_;       // --scene-root, "" when not given
};

// The command-line flags that override a scene's own settings (--width, --spp, --lookfrom, ...),
// shared by `rtvk render` and `rtvk bench`: registered on a command, then read back as
// scene_overrides once the command line is parsed.
class scene_flags {
 public:
  void add_to(CLI::App& cmd);

  // The flags given, each as typed (checked when applied).
  scene_overrides overrides() const;
  // Where the scene file's own files may lie.
  file_access access() const { return paths_.access(); }

 private:
  void add_lens_to(CLI::App& cmd);  // the calibrated cameras' flags

  // Each flag's value as CLI11 parsed it (units as in scene_overrides), then its option, which
  // tells whether it was given.
  int width_ = 0;
  std::string aspect_;
  int spp_ = 0;
  int depth_ = 0;
  long long seed_ = 0;
  std::string lookfrom_, lookat_, vup_;
  double vfov_ = 0, aperture_ = 0, focus_dist_ = 0, orbit_ = 0, fisheye_fov_ = 0;
  std::string projection_;
  std::string shutter_;
  std::string sampling_;
  std::string view_transform_;
  double exposure_ = 0;
  std::string calibration_, intrinsics_, distortion_, rolling_shutter_, colmap_;
  std::string environment_;
  CLI::Option* width_opt_ = nullptr;
  CLI::Option* aspect_opt_ = nullptr;
  CLI::Option* spp_opt_ = nullptr;
  CLI::Option* depth_opt_ = nullptr;
  CLI::Option* seed_opt_ = nullptr;
  CLI::Option* lookfrom_opt_ = nullptr;
  CLI::Option* lookat_opt_ = nullptr;
  CLI::Option* vup_opt_ = nullptr;
  CLI::Option* vfov_opt_ = nullptr;
  CLI::Option* aperture_opt_ = nullptr;
  CLI::Option* focus_dist_opt_ = nullptr;
  CLI::Option* orbit_opt_ = nullptr;
  CLI::Option* projection_opt_ = nullptr;
  CLI::Option* fisheye_fov_opt_ = nullptr;
  CLI::Option* shutter_opt_ = nullptr;
  CLI::Option* sampling_opt_ = nullptr;
  CLI::Option* view_transform_opt_ = nullptr;
  CLI::Option* exposure_opt_ = nullptr;
  CLI::Option* calibration_opt_ = nullptr;
  CLI::Option* intrinsics_opt_ = nullptr;
  CLI::Option* distortion_opt_ = nullptr;
  CLI::Option* rolling_shutter_opt_ = nullptr;
  CLI::Option* colmap_opt_ = nullptr;
  CLI::Option* environment_opt_ = nullptr;
  scene_path_flags paths_;
};

}  // namespace rtvk
