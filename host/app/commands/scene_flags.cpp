#include "scene_flags.h"

#include <filesystem>
#include <optional>

#include "errors.h"
#include "image_size.h"
#include "render_settings.h"

namespace rtvk {
namespace {

// The value when its option was given on the command line.
template <typename T>
std::optional<T> if_given(const CLI::Option* o, const T& value) {
  if (o && o->count() > 0) return value;
  return std::nullopt;
}

}  // namespace

void scene_path_flags::add_to(CLI::App& cmd) {
  const std::string group = "Scene files' paths (docs/farm.md)";
  CLI::Option* any =
      cmd.add_flag("--allow-any-path", any_path_,
                   "Let a scene file name textures and meshes anywhere (.., absolute paths, "
                   "symlinks out), not only in its own folder")
          ->group(group);
  cmd.add_option("--scene-root", root_,
                 "The folder a scene file's textures and meshes must lie in, instead of the scene "
                 "file's own folder")
      ->type_name("DIR")
      ->excludes(any)
      ->group(group);
}

file_access scene_path_flags::access() const {
  file_access a;
  a.any_path = any_path_;
  if (!root_.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_directory(root_, ec))
      throw usage_error("--scene-root " + root_ + ": not a folder");
    a.root = root_;
  }
  return a;
}

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
  projection_opt_ =
      cmd.add_option("--projection", projection_,
                     "Camera model: " + projection_names() +
                         " (equirectangular: the full sphere, square pixels at --aspect 2:1; "
                         "fisheye: a round image touching the top and bottom edges)")
          ->group(group);
  fisheye_fov_opt_ = cmd.add_option("--fisheye-fov", fisheye_fov_,
                                    "Fisheye field of view across the circle, degrees, in "
                                    "(0, 360] (default 180)")
                         ->group(group);
  shutter_opt_ = cmd.add_option("--shutter", shutter_,
                                "Shutter interval OPEN:CLOSE in seconds after each frame's time "
                                "(default 0:0, an instant): each sample's instant is drawn in it, "
                                "and moving spheres blur")
                     ->group(group);
  orbit_opt_ = cmd.add_option("--orbit", orbit_,
                              "Turn the camera about the up axis through its look-at point, one "
                              "turn in this many seconds (the built-in orbit path)")
                   ->group(group);
  sampling_opt_ = cmd.add_option("--sampling", sampling_,
                                 "How diffuse surfaces and media pick directions: plain (the first "
                                 "two books'), lights (the third book's: half toward the lights, "
                                 "stratified pixels), nee (next-event estimation: a lamp sample "
                                 "and a shadow ray a vertex, multiple importance sampling) or auto "
                                 "(default: lights where the scene has lights)")
                      ->group(group);
  environment_opt_ =
      cmd.add_option("--environment", environment_,
                     "HDR environment map FILE[:STRENGTH] (Radiance .hdr or OpenEXR .exr, "
                     "equirectangular, Blender's convention; docs/lighting.md): what rays that "
                     "escape see instead of the sky, times STRENGTH (default 1)")
          ->group(group);
  view_transform_opt_ =
      cmd.add_option("--view-transform", view_transform_,
                     "How 8-bit images (PNG, PPM, the viewer) encode the scene-linear light: "
                     "standard (sRGB), filmic, agx (Blender 4's), linear or gamma (the scene's "
                     "power law); default: the scene's (docs/color.md)")
          ->group(group);
  exposure_opt_ = cmd.add_option("--exposure", exposure_,
                                 "Exposure in stops (EV), -16 to 16: the light times 2^EV before "
                                 "the view transform; .exr keeps the unscaled light (default: the "
                                 "scene's, 0)")
                      ->group(group);
  add_lens_to(cmd);
  paths_.add_to(cmd);
}

void scene_flags::add_lens_to(CLI::App& cmd) {
  const std::string lens = "Calibrated cameras (docs/camera.md)";
  calibration_opt_ = cmd.add_option("--calibration", calibration_,
                                    "OpenCV calibration file (cv::FileStorage YAML or JSON: "
                                    "camera_matrix, distortion_coefficients, image size): the "
                                    "opencv or opencv-fisheye model, its intrinsics and image size")
                         ->group(lens);
  colmap_opt_ = cmd.add_option("--colmap", colmap_,
                               "COLMAP model folder (cameras.txt, images.txt, or .bin): one camera "
                               "per image, named after it, all rendered unless --camera picks")
                    ->group(lens);
  intrinsics_opt_ = cmd.add_option("--intrinsics", intrinsics_,
                                   "fx,fy,cx,cy in pixels (OpenCV's: pixel (0,0)'s center at "
                                   "0,0); cylindrical: fx in pixels per radian")
                        ->group(lens);
  distortion_opt_ = cmd.add_option("--distortion", distortion_,
                                   "Distortion coefficients: opencv k1,k2,p1,p2[,k3[,k4,k5,k6]], "
                                   "opencv-fisheye k1,k2,k3,k4, fisheye-polynomial k0,..,k4 "
                                   "(radians per pixel^n)")
                        ->group(lens);
  rolling_shutter_opt_ =
      cmd.add_option("--rolling-shutter", rolling_shutter_,
                     "Rolling shutter [top-down:|bottom-up:]SECONDS: each row opens later by its "
                     "share of the readout time, and stays open for --shutter")
          ->group(lens);
}

scene_overrides scene_flags::overrides() const {
  return {.width = if_given(width_opt_, width_),
          .aspect = if_given(aspect_opt_, aspect_),
          .spp = if_given(spp_opt_, spp_),
          .depth = if_given(depth_opt_, depth_),
          .seed = if_given(seed_opt_, seed_),
          .lookfrom = if_given(lookfrom_opt_, lookfrom_),
          .lookat = if_given(lookat_opt_, lookat_),
          .vup = if_given(vup_opt_, vup_),
          .vfov = if_given(vfov_opt_, vfov_),
          .aperture = if_given(aperture_opt_, aperture_),
          .focus_dist = if_given(focus_dist_opt_, focus_dist_),
          .projection = if_given(projection_opt_, projection_),
          .fisheye_fov = if_given(fisheye_fov_opt_, fisheye_fov_),
          .shutter = if_given(shutter_opt_, shutter_),
          .orbit = if_given(orbit_opt_, orbit_),
          .sampling = if_given(sampling_opt_, sampling_),
          .view_transform = if_given(view_transform_opt_, view_transform_),
          .exposure = if_given(exposure_opt_, exposure_),
          .calibration = if_given(calibration_opt_, calibration_),
          .intrinsics = if_given(intrinsics_opt_, intrinsics_),
          .distortion = if_given(distortion_opt_, distortion_),
          .rolling_shutter = if_given(rolling_shutter_opt_, rolling_shutter_),
          .colmap = if_given(colmap_opt_, colmap_),
          .environment = if_given(environment_opt_, environment_)};
}

}  // namespace rtvk
