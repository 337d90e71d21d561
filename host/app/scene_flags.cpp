#include "scene_flags.h"

#include <cmath>

#include "errors.h"
#include "format.h"
#include "parse_values.h"

namespace rtvk {
namespace {

bool given(const CLI::Option* o) {
  return o && o->count() > 0;
}

double checked(double v, bool ok, const std::string& flag, const std::string& expected) {
  if (!ok || !std::isfinite(v))
    throw usage_error(flag + ": " + format_number(v) + " is not " + expected);
  return v;
}

}  // namespace

void scene_flags::add_to(CLI::App& cmd) {
  const std::string group = "Scene overrides (default: the scene's own settings)";
  width_opt_ = cmd.add_option("--width", width_, "Image width in pixels")
                   ->check(CLI::Range(1, max_image_side))
                   ->group(group);
  aspect_opt_ = cmd.add_option("--aspect", aspect_, "Aspect ratio, W:H or a decimal")->group(group);
  spp_opt_ = cmd.add_option("--spp", spp_, "Samples per pixel")
                 ->check(CLI::Range(1, max_spp))
                 ->group(group);
  depth_opt_ = cmd.add_option("--depth", depth_, "Most bounces per path")
                   ->check(CLI::Range(1, max_depth_limit))
                   ->group(group);
  seed_opt_ = cmd.add_option("--seed", seed_, "Random seed (same seed, same image)")
                  ->check(CLI::Range(0ll, 0xffffffffll))
                  ->group(group);
  lookfrom_opt_ = cmd.add_option("--lookfrom", lookfrom_, "Camera position x,y,z")->group(group);
  lookat_opt_ = cmd.add_option("--lookat", lookat_, "Point looked at x,y,z")->group(group);
  vup_opt_ = cmd.add_option("--vup", vup_, "Up direction x,y,z")->group(group);
  vfov_opt_ = cmd.add_option("--vfov", vfov_, "Vertical field of view, degrees")->group(group);
  aperture_opt_ =
      cmd.add_option("--aperture", aperture_, "Lens diameter (0: pinhole)")->group(group);
  focus_dist_opt_ = cmd.add_option("--focus-dist", focus_dist_, "Distance in focus")->group(group);
  orbit_opt_ = cmd.add_option("--orbit", orbit_,
                              "Turn the camera about the up axis through its look-at point, one "
                              "turn in this many seconds (the built-in orbit path)")
                   ->group(group);
}

void scene_flags::apply(scene& s) const {
  render_settings& r = s.render;
  if (given(width_opt_)) r.width = width_;
  if (given(aspect_opt_)) r.aspect = parse_aspect(aspect_);
  if (given(spp_opt_)) r.spp = spp_;
  if (given(depth_opt_)) r.max_depth = depth_;
  if (given(seed_opt_)) r.seed = std::uint32_t(seed_);
  const bool pose_flags = given(lookfrom_opt_) || given(lookat_opt_) || given(vup_opt_) ||
                          given(vfov_opt_) || given(aperture_opt_) || given(focus_dist_opt_);
  for (named_camera& cam : s.cameras) {
    if (cam.path.motion == camera_motion::keyframes && (pose_flags || given(orbit_opt_)))
      throw usage_error(std::string(given(orbit_opt_) ? "--orbit" : "a camera pose flag") +
                        ": camera " + cam.name + " of " + s.name +
                        " moves by keyframes; pick another with --camera or edit its keyframes");
    camera_pose& c = cam.path.pose;
    if (given(lookfrom_opt_)) c.lookfrom = parse_vec3(lookfrom_, "--lookfrom");
    if (given(lookat_opt_)) c.lookat = parse_vec3(lookat_, "--lookat");
    if (given(vup_opt_)) c.vup = parse_vec3(vup_, "--vup");
    if (given(vfov_opt_))
      c.vfov = checked(vfov_, vfov_ > 0 && vfov_ < 180, "--vfov", "in (0, 180) degrees");
    if (given(aperture_opt_)) c.aperture = checked(aperture_, aperture_ >= 0, "--aperture", ">= 0");
    if (given(focus_dist_opt_))
      c.focus_dist = checked(focus_dist_, focus_dist_ > 0, "--focus-dist", "> 0");
    if (given(orbit_opt_)) {
      cam.path.motion = camera_motion::orbit;
      cam.path.orbit_period = checked(orbit_, orbit_ > 0, "--orbit", "> 0 seconds");
    }
  }
}

camera scene_flags::make_camera(const scene& s, const camera_pose& pose,
                                const std::string& what) const {
  try {
    return camera(pose, s.render.aspect, s.render.width);
  } catch (const std::invalid_argument& e) {
    const std::string aspect = given(aspect_opt_) ? aspect_ : format_number(s.render.aspect);
    throw usage_error("--width " + std::to_string(s.render.width) + " / --aspect " + aspect +
                      " / " + what + ": " + e.what());
  }
}

}  // namespace rtvk
