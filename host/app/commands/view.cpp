#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "commands.h"
#include "errors.h"
#include "gpu_flags.h"
#include "image_io.h"
#include "interrupt.h"
#include "output_pattern.h"
#include "scene.h"
#include "scene_file.h"
#include "scene_flags.h"
#include "viewer.h"

namespace rtvk {
namespace {

struct view_options {
  std::string scene = "seed";  // built-in scene name or .json file
  std::string camera;          // the scene's camera to start from; default: the first
  std::string accel = "bvh";   // bvh or none
  gpu_flags gpu;               // --device, --validate, --gpu-timeout
  std::string screenshot;      // write the image at --spp samples here, then exit
  scene_flags flags;           // --width, --spp, --lookfrom, ...
};

// The shortest text that reads back as the same double: printed flags reproduce the frame.
std::string exact(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string xyz(const vec3& v) {
  return exact(v.x) + "," + exact(v.y) + "," + exact(v.z);
}

// The camera as `rtvk render` flags, so the framed shot can be rendered or sent to the farm.
std::string render_flags(const std::string& scene_name, const view::viewer_result& r) {
  const camera_pose& p = r.pose;
  std::string f =
      "rtvk render --scene " + scene_name + " --width " + std::to_string(r.width) + " --aspect " +
      exact(r.aspect) + " --spp " + std::to_string(std::max(r.samples, 1)) + " --lookfrom " +
      xyz(p.lookfrom) + " --lookat " + xyz(p.lookat) + " --vup " + xyz(p.vup) + " --vfov " +
      exact(p.vfov) + " --aperture " + exact(p.aperture) + " --focus-dist " + exact(p.focus_dist) +
      " --projection " + std::string(projection_name(p.projection));
  if (p.projection == projection::fisheye_equidistant ||
      p.projection == projection::fisheye_equisolid || p.projection == projection::cylindrical ||
      p.projection == projection::fisheye_polynomial)
    f += " --fisheye-fov " + exact(p.fisheye_fov);
  // A calibration's own intrinsics (for its image size) come back with --calibration or --colmap;
  // ones given in the render's pixels are written out.
  const lens_intrinsics& l = p.intrinsics;
  if (is_calibrated(p.projection) && l.width == 0 && (l.fx != 0 || l.fy != 0))
    f += " --intrinsics " + exact(l.fx) + "," + exact(l.fy) + "," + exact(l.cx) + "," + exact(l.cy);
  if (is_calibrated(p.projection) && l.k != decltype(l.k){}) {
    f += " --distortion ";
    for (std::size_t k = 0; k < l.k.size(); ++k) f += (k ? "," : "") + exact(l.k[k]);
  }
  if (p.readout != 0)
    f += std::string(" --rolling-shutter ") + (p.readout > 0 ? "top-down:" : "bottom-up:") +
         exact(std::abs(p.readout));
  if (p.shutter_open != 0 || p.shutter_close != 0)
    f += " --shutter " + exact(p.shutter_open) + ":" + exact(p.shutter_close);
  return f;
}

int run_view(view_options o) {
  const interrupt_guard signals;  // SIGINT, SIGTERM: close the window cleanly
  if (!o.screenshot.empty()) output_pattern(o.screenshot, "--screenshot");  // checked up front
  scene s = load_scene(o.scene, o.flags.access());
  // What the loaders drew otherwise than the files ask (a missing MTL drawn gray), said once.
  for (const std::string& w : s.warnings) std::fprintf(stderr, "rtvk: warning: %s\n", w.c_str());
  const scene_overrides overrides = o.flags.overrides();
  overrides.apply_cameras(s);  // --colmap's views (--camera picks one), a calibration's size
  overrides.apply(s);
  check_scene(s);
  s.motion = shutter_span(s, 0);  // the viewer shows time 0, from any of the scene's cameras
  const camera_path* path = &main_camera(s);
  if (!o.camera.empty()) {
    path = nullptr;
    for (const named_camera& c : s.cameras)
      if (c.name == o.camera) path = &c.path;
    if (!path) throw usage_error("--camera " + o.camera + ": the scene has no such camera");
  }
  const camera_pose pose = path->at(0);
  // Refuses impossible poses and sizes up front, and a screenshot too large for its format.
  const camera cam = overrides.make_camera(s, pose, "the view");
  if (!o.screenshot.empty())
    check_output_size(o.screenshot, cam.image_width(), cam.image_height(), "--screenshot");

  view::viewer_options v;
  v.gpu = o.gpu.options();
  v.render.engine.use_bvh = o.accel == "bvh";
  // A screenshot is the image rtvk render makes with the same flags: the scene's size.
  // A calibrated lens is for its calibration's aspect ratio: the window does not reshape it.
  const bool calibrated = is_calibrated(pose.projection) && pose.intrinsics.width > 0;
  v.size_follows_window =
      !overrides.width && !overrides.aspect && o.screenshot.empty() && !calibrated;
  v.exit_at_target = !o.screenshot.empty();
  v.target_spp = o.screenshot.empty() && !overrides.spp ? 0 : s.render.spp;
  v.cancelled = interrupt_requested();
  view::viewer_actions actions;
  actions.print = [&](const view::viewer_result& r) {
    // The same frame twice: as flags, and as a camera to paste into a scene file.
    std::printf("%s\n\"camera\": %s\n", render_flags(o.scene, r).c_str(),
                dump_camera_json(r.pose).c_str());
    std::fflush(stdout);
  };
  int shots = 0;
  actions.screenshot = [&](const view::viewer_result& r) {
    std::string name;  // the next number whose file is not there: earlier sessions' shots stay
    do name = "rtvk-view-" + std::to_string(++shots) + ".png";
    while (std::filesystem::exists(name));
    write_image(r.image, name);
    std::fprintf(stderr, "rtvk: %dx%d, %d spp -> %s\n", r.width, r.height, r.samples, name.c_str());
  };
  const view::viewer_result r = view::run_viewer(s, pose, v, actions);

  const bool interrupted = pending_signal() != 0;
  actions.print(r);
  std::fprintf(
      stderr, "rtvk: %d frames in %.1f s (%.1f frames/s), %.3g Msamples/s; %dx%d at %d spp\n",
      r.frames, r.seconds, r.seconds > 0 ? r.frames / r.seconds : 0.0,
      r.seconds > 0 ? r.pixel_samples / r.seconds / 1e6 : 0.0, r.width, r.height, r.samples);
  if (!o.screenshot.empty() && !interrupted && r.samples == s.render.spp) {
    write_image(r.image, o.screenshot);
    std::fprintf(stderr, "rtvk: %s %dx%d, %d spp, viewed -> %s\n", s.name.c_str(), r.width,
                 r.height, r.samples, o.screenshot.c_str());
  } else if (!o.screenshot.empty()) {
    std::fprintf(stderr, "rtvk: the window closed at %d of %d samples; %s was not written\n",
                 r.samples, s.render.spp, o.screenshot.c_str());
  }
  return 0;
}

}  // namespace

command_action add_view_command(CLI::App& app) {
  auto o = std::make_shared<view_options>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Open a window and render progressively on a Vulkan device (needs a display)");
  cmd->add_option(
         "--scene,scene", o->scene,
         "Built-in scene (also spheres:N), a .json scene file or a mesh (.obj, .gltf, .glb)")
      ->capture_default_str();
  cmd->add_option("--camera", o->camera, "Camera of the scene to start from; default: the first");
  o->gpu.add_to(*cmd);
  cmd->add_option("--accel", o->accel, "bvh, or none to test every sphere (same image, slower)")
      ->check(CLI::IsMember({"bvh", "none"}))
      ->capture_default_str();
  cmd->add_option("--screenshot", o->screenshot,
                  "Render to --spp samples in the window, write the image here (.png or .ppm, "
                  "the bytes rtvk render --backend gpu writes) and exit");
  o->flags.add_to(*cmd);
  return [o] { return run_view(*o); };
}

}  // namespace rtvk
