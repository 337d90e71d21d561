#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "camera.h"
#include "scene.h"

namespace rtvk {

// The command-line flags that override a scene's own settings (--width, --spp, --lookfrom, ...),
// shared by `rtvk render` and `rtvk bench`. Each applies only when given.
class scene_flags {
 public:
  void add_to(CLI::App& cmd);

  // The scene's settings with the given flags applied, to every camera in s.cameras (narrow
  // them to the chosen ones first). Throws usage_error naming the flag.
  void apply(scene& s) const;

  // The camera for `pose` in the scene; an impossible combination (a height over the limit, a
  // camera looking at itself) is a usage_error naming the flags involved and `what` (the camera).
  camera make_camera(const scene& s, const camera_pose& pose, const std::string& what) const;

 private:
  int width_ = 0;
  std::string aspect_;
  int spp_ = 0;
  int depth_ = 0;
  long long seed_ = 0;
  std::string lookfrom_, lookat_, vup_;
  double vfov_ = 0, aperture_ = 0, focus_dist_ = 0, orbit_ = 0;
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
};

}  // namespace rtvk
