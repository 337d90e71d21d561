#include "scene_overrides.h"

#include <cmath>
#include <cstdlib>

#include "calibration_file.h"
#include "colmap_model.h"
#include "errors.h"
#include "format.h"
#include "light_sources.h"
#include "parse_values.h"
#include "scene_file.h"

namespace rtvk {
namespace {

double checked(double v, bool ok, const std::string& flag, const std::string& expected) {
  if (!ok || !std::isfinite(v))
    throw usage_error(flag + ": " + format_number(v) + " is not " + expected);
  return v;
}

// The image size a calibration was made at, unless --width or --aspect says otherwise: with
// --width alone the intrinsics scale to it (camera_lens.cpp).
void calibrated_size(const scene_overrides& o, scene& s, int width, int height) {
  if (!o.aspect) s.render.aspect = exact_aspect(width, height);
  if (!o.width) s.render.width = width;
}

// DIRECTION:SECONDS (top-down or bottom-up) or SECONDS (top-down): the signed readout.
double parse_rolling_shutter(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string direction = colon == std::string::npos ? "top-down" : text.substr(0, colon);
  const std::string seconds = colon == std::string::npos ? text : text.substr(colon + 1);
  if (direction != "top-down" && direction != "bottom-up")
    throw usage_error("--rolling-shutter " + text +
                      ": expected [top-down:|bottom-up:]SECONDS, e.g. top-down:0.03");
  const double readout =
      parse_numbers(seconds, "--rolling-shutter", 1, 1, "the readout time in seconds, >= 0")[0];
  if (!(readout >= 0))
    throw usage_error("--rolling-shutter " + text + ": the readout time must be >= 0 seconds");
  return direction == "top-down" ? readout : -readout;
}

// --environment FILE[:STRENGTH]: the map escaping rays see, replacing the scene's own (whose
// rotation and visibility it keeps) or the sky. A suffix after the last colon that is not a number
// is part of the file's name.
void apply_environment(const std::string& text, scene& s) {
  std::string file = text;
  double strength = s.environment ? s.environment->strength : 1.0;
  const std::size_t colon = text.rfind(':');
  if (colon != std::string::npos) {
    const std::string tail = text.substr(colon + 1);
    char* end = nullptr;
    const double v = std::strtod(tail.c_str(), &end);
    if (!tail.empty() && end == tail.c_str() + tail.size()) {
      if (!(v >= 0 && v <= 1e9))
        throw usage_error("--environment " + text +
                          ": the strength must be a number from 0 to 1e9");
      strength = v;
      file = text.substr(0, colon);
    }
  }
  if (file.empty()) throw usage_error("--environment " + text + ": expected FILE[:STRENGTH]");
  environment_map e = s.environment ? *s.environment : environment_map{};
  e.file = file;
  e.strength = strength;
  e.image = load_environment_image(file, "--environment");
  s.environment = std::move(e);
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
    else if (*o.sampling == "nee")
      r.sampling = sampling_mode::nee;
    else
      throw usage_error("--sampling " + *o.sampling + ": expected plain, lights, nee or auto");
  }
  if (o.view_transform) {
    const auto t = view_transform_from_name(*o.view_transform);
    if (!t)
      throw usage_error("--view-transform " + *o.view_transform + ": expected " +
                        view_transform_words);
    r.transform = *t;
  }
  if (o.exposure)
    r.exposure = checked(*o.exposure, std::abs(*o.exposure) <= max_exposure, "--exposure",
                         "in [-16, 16] EV");
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

// The calibrated models' intrinsics from --calibration, --intrinsics and --distortion (in that
// order: the flags adjust a file's values).
void apply_lens(const scene_overrides& o, const std::optional<calibration>& cal, camera_pose& c) {
  if (cal) {  // a calibrated camera is a pinhole with a lens model: no aperture
    c.projection = cal->model;
    c.intrinsics = cal->lens;
    if (!o.aperture) c.aperture = 0;  // (one asked for is refused by the camera)
  }
  if (o.intrinsics) {
    const std::vector<double> v =
        parse_numbers(*o.intrinsics, "--intrinsics", 4, 4, "fx,fy,cx,cy in pixels");
    c.intrinsics.fx = v[0];
    c.intrinsics.fy = v[1];
    c.intrinsics.cx = v[2];
    c.intrinsics.cy = v[3];
  }
  if (o.distortion) {
    const std::vector<double> v = parse_numbers(
        *o.distortion, "--distortion", 1, 8,
        "1 to 8 coefficients: opencv k1,k2,p1,p2[,k3[,k4,k5,k6]], opencv-fisheye k1..k4, "
        "fisheye-polynomial k0..k4");
    c.intrinsics.k = {};
    std::copy(v.begin(), v.end(), c.intrinsics.k.begin());
  }
  if (o.rolling_shutter) c.readout = parse_rolling_shutter(*o.rolling_shutter);
}

// --intrinsics and --distortion only where the model reads them, and no more coefficients than
// it has: ignoring them would draw another lens than the one asked for.
void check_lens_flags(const scene_overrides& o, projection p) {
  const std::string model(projection_name(p));
  if (o.intrinsics && !is_calibrated(p))
    throw usage_error("--intrinsics " + *o.intrinsics + ": the " + model +
                      " model takes none (calibrated models: opencv, opencv-fisheye, "
                      "fisheye-polynomial, cylindrical)");
  if (!o.distortion) return;
  const std::size_t most = p == projection::opencv               ? 8
                           : p == projection::opencv_fisheye     ? 4
                           : p == projection::fisheye_polynomial ? 5
                                                                 : 0;
  const std::size_t given = parse_numbers(*o.distortion, "--distortion", 1, 8, "numbers").size();
  if (given > most)
    throw usage_error("--distortion " + *o.distortion + ": the " + model + " model takes " +
                      (most == 0 ? std::string("no coefficients")
                                 : "at most " + std::to_string(most) + " coefficients") +
                      ", got " + std::to_string(given));
}

// The camera model: not a move, so it applies to every pose of a path, keyframes included.
void apply_model(const scene_overrides& o, const std::optional<calibration>& cal, camera_pose& c) {
  apply_lens(o, cal, c);
  if (o.projection) {
    const std::optional<projection> p = projection_from_name(*o.projection);
    if (!p)
      throw usage_error("--projection " + *o.projection + ": not a projection; expected one of " +
                        projection_names());
    if (cal && *p != cal->model)
      throw usage_error("--projection " + *o.projection + ": --calibration " + *o.calibration +
                        " is for the " + std::string(projection_name(cal->model)) + " model");
    c.projection = *p;
  }
  if (o.fisheye_fov)
    c.fisheye_fov = checked(*o.fisheye_fov, *o.fisheye_fov > 0 && *o.fisheye_fov <= 360,
                            "--fisheye-fov", "in (0, 360] degrees");
  check_lens_flags(o, c.projection);
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

double exact_aspect(int width, int height) {
  double a = double(width) / height;
  while (int(width / a) < height) a = std::nextafter(a, 0.0);
  while (int(width / a) > height) a = std::nextafter(a, 1e300);
  return a;
}

void scene_overrides::apply_cameras(scene& s) const {
  if (colmap && calibration)
    throw usage_error("--calibration " + *calibration + ": --colmap " + *colmap +
                      " has its own cameras' intrinsics");
  if (colmap) {
    const std::vector<colmap_view> views = read_colmap_model(*colmap);
    s.cameras.clear();
    for (const colmap_view& v : views) {
      const lens_intrinsics& a = views.front().pose.intrinsics;
      const lens_intrinsics& b = v.pose.intrinsics;
      if (a.width != b.width || a.height != b.height)
        throw usage_error("--colmap " + *colmap + ": image " + v.image_name + " is " +
                          std::to_string(b.width) + "x" + std::to_string(b.height) + ", " +
                          views.front().image_name + " " + std::to_string(a.width) + "x" +
                          std::to_string(a.height) + ": rtvk renders one size per run");
      camera_path path;
      path.pose = v.pose;
      s.cameras.push_back({v.name, path});
    }
    const lens_intrinsics& l = views.front().pose.intrinsics;
    calibrated_size(*this, s, l.width, l.height);
  }
  if (calibration) {
    const rtvk::calibration cal = read_opencv_calibration(*calibration);
    calibrated_size(*this, s, cal.lens.width, cal.lens.height);
  }
}

void scene_overrides::apply(scene& s) const {
  if (colmap && calibration)
    throw usage_error("--calibration " + *calibration + ": --colmap " + *colmap +
                      " has its own cameras' intrinsics");
  std::optional<rtvk::calibration> cal;
  if (calibration) cal = read_opencv_calibration(*calibration);
  apply_render(*this, s.render);
  resolve_sampling(s);
  if (environment) apply_environment(*environment, s);
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
    apply_model(*this, cal, cam.path.pose);
    for (camera_keyframe& k : cam.path.keyframes) apply_model(*this, cal, k.pose);
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
