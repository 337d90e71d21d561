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
}

void scene_flags::apply(scene& s) const {
  render_settings& r = s.render;
  if (given(width_opt_)) r.width = width_;
  if (given(aspect_opt_)) r.aspect = parse_aspect(aspect_);
  if (given(spp_opt_)) r.spp = spp_;
  if (given(depth_opt_)) r.max_depth = depth_;
  if (given(seed_opt_)) r.seed = std::uint32_t(seed_);
  camera_pose& c = s.camera;
  if (given(lookfrom_opt_)) c.lookfrom = parse_vec3(lookfrom_, "--lookfrom");
  if (given(lookat_opt_)) c.lookat = parse_vec3(lookat_, "--lookat");
  if (given(vup_opt_)) c.vup = parse_vec3(vup_, "--vup");
  if (given(vfov_opt_))
    c.vfov = checked(vfov_, vfov_ > 0 && vfov_ < 180, "--vfov", "in (0, 180) degrees");
  if (given(aperture_opt_)) c.aperture = checked(aperture_, aperture_ >= 0, "--aperture", ">= 0");
  if (given(focus_dist_opt_))
    c.focus_dist = checked(focus_dist_, focus_dist_ > 0, "--focus-dist", "> 0");
}

camera scene_flags::make_camera(const scene& s, const std::string& scene_name) const {
  try {
    return camera(s.camera, s.render.aspect, s.render.width);
  } catch (const std::invalid_argument& e) {
    const std::string aspect = given(aspect_opt_) ? aspect_ : format_number(s.render.aspect);
    throw usage_error("--width " + std::to_string(s.render.width) + " / --aspect " + aspect +
                      " / camera of " + scene_name + ": " + e.what());
  }
}

}  // namespace rtvk
