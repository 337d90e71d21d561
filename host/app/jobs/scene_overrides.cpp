#include "scene_overrides.h"

#include <cmath>

#include "errors.h"
#include "format.h"
#include "light_sources.h"
#include "parse_values.h"

namespace rtvk {
namespace {

double checked(double v, bool ok, const std::string& flag, const std::string& expected) {
  if (!ok || !std::isfinite(v))
    throw usage_error(flag + ": " + format_number(v) + " is not " + expected);
  return v;
}

bool moves_pose(const scene_overrides& o) {
  return o.lookfrom || o.lookat || o.vup || o.vfov || o.aperture || o.focus_dist;
}

void apply_render(const scene_overrides& o, render_settings& r) {
  if (o.width) r.width = *o.width;
  if (o.aspect) r.aspect = parse_aspect(*o.aspect);
  if (o.spp) r.spp = *o.spp;
  if (o.depth) r.max_depth = *o.depth;
  if (o.seed) r.seed = std::uint32_t(*o.seed);
  if (o.sampling) {
    if (*o.sampling == "plain")
      r.sampling = sampling_mode::plain;
    else if (*o.sampling == "lights")
      r.sampling = sampling_mode::lights;
    else if (*o.sampling == "auto")
      r.sampling = sampling_mode::automatic;
    else
      throw usage_error("--sampling " + *o.sampling + ": expected plain, lights or auto");
  }
}

void apply_pose(const scene_overrides& o, camera_pose& c) {
  if (o.lookfrom) c.lookfrom = parse_vec3(*o.lookfrom, "--lookfrom");
  if (o.lookat) c.lookat = parse_vec3(*o.lookat, "--lookat");
  if (o.vup) c.vup = parse_vec3(*o.vup, "--vup");
  if (o.vfov)
    c.vfov = checked(*o.vfov, *o.vfov > 0 && *o.vfov < 180, "--vfov", "in (0, 180) degrees");
  if (o.aperture) c.aperture = checked(*o.aperture, *o.aperture >= 0, "--aperture", ">= 0");
  if (o.focus_dist) c.focus_dist = checked(*o.focus_dist, *o.focus_dist > 0, "--focus-dist", "> 0");
}

// The camera model: not a move, so it applies to every pose of a path, keyframes included.
void apply_model(const scene_overrides& o, camera_pose& c) {
  if (o.projection) {
    const std::optional<projection> p = projection_from_name(*o.projection);
    if (!p)
      throw usage_error("--projection " + *o.projection + ": not a projection; expected one of " +
                        projection_names());
    c.projection = *p;
  }
  if (o.fisheye_fov)
    c.fisheye_fov = checked(*o.fisheye_fov, *o.fisheye_fov > 0 && *o.fisheye_fov <= 360,
                            "--fisheye-fov", "in (0, 360] degrees");
  if (o.shutter) {
    const std::size_t colon = o.shutter->find(':');
    double open = 0, close = 0;
    try {
      if (colon == std::string::npos) throw std::invalid_argument("no colon");
      std::size_t used_open = 0, used_close = 0;
      const std::string a = o.shutter->substr(0, colon), b = o.shutter->substr(colon + 1);
      open = std::stod(a, &used_open);
      close = std::stod(b, &used_close);
      if (used_open != a.size() || used_close != b.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
      throw usage_error("--shutter " + *o.shutter + ": expected OPEN:CLOSE in seconds, e.g. 0:1");
    }
    if (!std::isfinite(open) || !std::isfinite(close) || !(open <= close))
      throw usage_error("--shutter " + *o.shutter +
                        ": the shutter must open no later than it closes, both finite");
    c.shutter_open = open;
    c.shutter_close = close;
  }
}

}  // namespace

void scene_overrides::apply(scene& s) const {
  apply_render(*this, s.render);
  try {  // lights asked of a scene without (or with too many)
    check_sampling(s, s.render, sampling ? "--sampling" : s.name + ": /render/sampling");
  } catch (const std::invalid_argument& e) {
    throw usage_error(e.what());
  }
  const bool pose_flags = moves_pose(*this);
  for (named_camera& cam : s.cameras) {
    // A keyframed path has no one pose to override.
    if (cam.path.motion == camera_motion::keyframes && (pose_flags || orbit))
      throw usage_error(std::string(orbit ? "--orbit" : "a camera pose flag") + ": camera " +
                        cam.name + " of " + s.name +
                        " moves by keyframes; pick another with --camera or edit its keyframes");
    apply_pose(*this, cam.path.pose);
    apply_model(*this, cam.path.pose);
    for (camera_keyframe& k : cam.path.keyframes) apply_model(*this, k.pose);
    if (orbit) {
      cam.path.motion = camera_motion::orbit;
      cam.path.orbit_period = checked(*orbit, *orbit > 0, "--orbit", "> 0 seconds");
    }
  }
}

camera scene_overrides::make_camera(const scene& s, const camera_pose& pose,
                                    const std::string& what, double frame_time) const {
  try {
    return camera(pose, s.render.aspect, s.render.width, frame_time);
  } catch (const std::invalid_argument& e) {
    const std::string shown = aspect ? *aspect : format_number(s.render.aspect);
    throw usage_error("--width " + std::to_string(s.render.width) + " / --aspect " + shown + " / " +
                      what + ": " + e.what());
  }
}

}  // namespace rtvk
