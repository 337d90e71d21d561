// The scene file's cameras: one "camera" or named "cameras", each a pose (with a thin lens or a
// calibrated model's intrinsics), an orbit or keyframes; read and written side by side.
#include <cmath>

#include "camera_lens.h"
#include "format.h"
#include "scene_file.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

const std::set<std::string> pose_fields = {
    "lookfrom",   "lookat",           "vup",          "vfov",           "aperture",
    "focus_dist", "projection",       "fisheye_fov",  "shutter",        "intrinsics",
    "distortion", "calibration_size", "image_circle", "rolling_shutter"};

// A calibrated model's "intrinsics": [fx, fy, cx, cy] in pixels, with the focal lengths its
// model needs.
void read_intrinsics(const scene_reader& r, const json& j, const std::string& p, camera_pose& c) {
  lens_intrinsics& l = c.intrinsics;
  const std::string model(projection_name(c.projection));
  if (j.contains("intrinsics")) {
    const json& k = j["intrinsics"];
    if (!k.is_array() || k.size() != 4)
      r.fail(p + "/intrinsics",
             "expected [fx, fy, cx, cy] in pixels, got " +
                 (k.is_array() ? "an array of " + std::to_string(k.size()) : r.type_of(k)));
    l.fx = r.number(k[0], p + "/intrinsics/0");
    l.fy = r.number(k[1], p + "/intrinsics/1");
    l.cx = r.number(k[2], p + "/intrinsics/2");
    l.cy = r.number(k[3], p + "/intrinsics/3");
    // The polynomial fisheye reads only cx, cy; an uncalibrated cylinder has fx = fy = 0 (its
    // fields of view decide); the others need focal lengths.
    const bool needs_focal = c.projection == projection::opencv ||
                             c.projection == projection::opencv_fisheye ||
                             (c.projection == projection::cylindrical && (l.fx != 0 || l.fy != 0));
    if (needs_focal)
      for (int i = 0; i < 2; ++i) {
        const double f = i == 0 ? l.fx : l.fy;
        if (!(f > 0))
          r.fail(p + "/intrinsics/" + std::to_string(i),
                 std::string("expected a focal length ") + (i == 0 ? "fx" : "fy") +
                     " > 0 pixels for the " + model + " model, got " + format_number(f));
      }
  } else if (c.projection == projection::opencv || c.projection == projection::opencv_fisheye) {
    r.fail(p, "the " + model + " model needs \"intrinsics\": [fx, fy, cx, cy] in pixels");
  }
}

// "rolling_shutter": {"direction": "top-down" | "bottom-up", "readout": seconds}, as the
// camera's signed readout time (negative: bottom-up).
double read_rolling_shutter(const scene_reader& r, const json& s, const std::string& sp) {
  r.only_fields(s, sp, {"direction", "readout"});
  const double readout = r.number(r.required(s, sp, "readout"), sp + "/readout");
  if (readout < 0)
    r.fail(sp + "/readout",
           "expected the readout time >= 0 seconds, got " + format_number(readout));
  bool top_down = true;
  if (s.contains("direction")) {
    const json& d = s["direction"];
    if (!d.is_string() || (d != "top-down" && d != "bottom-up"))
      r.fail(sp + "/direction", "expected \"top-down\" or \"bottom-up\", got " +
                                    (d.is_string() ? d.dump() : r.type_of(d)));
    top_down = d == "top-down";
  }
  return top_down ? readout : -readout;
}

// The calibrated models' fields (docs/scene-format.md): intrinsics, distortion, the size they
// were calibrated at, the polynomial fisheye's image circle, and the rolling shutter. What the
// camera would refuse of them is refused here, at the field.
void read_lens(const scene_reader& r, const json& j, const std::string& p, camera_pose& c) {
  lens_intrinsics& l = c.intrinsics;
  read_intrinsics(r, j, p, c);
  if (j.contains("distortion")) {
    const json& k = j["distortion"];
    if (!k.is_array() || k.empty() || k.size() > l.k.size())
      r.fail(p + "/distortion",
             "expected 1 to 8 coefficients, got " +
                 (k.is_array() ? "an array of " + std::to_string(k.size()) : r.type_of(k)));
    l.k = {};
    for (std::size_t i = 0; i < k.size(); ++i)
      l.k[i] = r.number(k[i], p + "/distortion/" + std::to_string(i));
  }
  if (j.contains("calibration_size")) {
    const json& s = j["calibration_size"];
    if (!s.is_array() || s.size() != 2)
      r.fail(p + "/calibration_size", "expected [width, height] in pixels, got " + r.type_of(s));
    l.width = int(r.integer(s[0], p + "/calibration_size/0", 1, max_image_side));
    l.height = int(r.integer(s[1], p + "/calibration_size/1", 1, max_image_side));
  }
  if (j.contains("image_circle")) {
    l.radius = r.number(j["image_circle"], p + "/image_circle");
    if (l.radius < 0)
      r.fail(p + "/image_circle",
             "expected a radius >= 0 pixels (0: none), got " + format_number(l.radius));
  }
  if (j.contains("rolling_shutter"))
    c.readout = read_rolling_shutter(r, j["rolling_shutter"], p + "/rolling_shutter");
  // An opencv distortion that folds inside the image it was calibrated for: refused at the
  // distortion (without a size, the render's image is checked when it is made).
  if (c.projection == projection::opencv && l.width > 0 && l.fx > 0 && l.fy > 0) {
    camera_frame f{};
    try {
      setup_lens(c, l.width, l.height, f);
    } catch (const std::invalid_argument& e) {
      r.fail(p + (j.contains("distortion") ? "/distortion" : ""), e.what());
    }
  }
}

// The pose fields of `j` over the defaults; the caller has checked which fields may appear.
camera_pose read_pose(const scene_reader& r, const json& j, const std::string& p) {
  camera_pose c;
  if (j.contains("lookfrom")) c.lookfrom = r.vector3(j["lookfrom"], p + "/lookfrom");
  if (j.contains("lookat")) c.lookat = r.vector3(j["lookat"], p + "/lookat");
  if (j.contains("vup")) c.vup = r.vector3(j["vup"], p + "/vup");
  if (j.contains("vfov")) c.vfov = r.number(j["vfov"], p + "/vfov");
  if (j.contains("aperture")) c.aperture = r.number(j["aperture"], p + "/aperture");
  if (j.contains("focus_dist")) c.focus_dist = r.number(j["focus_dist"], p + "/focus_dist");
  if (j.contains("projection")) {
    const json& m = j["projection"];
    if (!m.is_string())
      r.fail(p + "/projection", "expected a projection name, got " + r.type_of(m));
    const std::optional<projection> model = projection_from_name(m.get<std::string>());
    if (!model)
      r.fail(p + "/projection", "unknown projection \"" + m.get<std::string>() +
                                    "\"; expected one of " + projection_names());
    c.projection = *model;
  }
  if (j.contains("fisheye_fov")) c.fisheye_fov = r.number(j["fisheye_fov"], p + "/fisheye_fov");
  if (j.contains("shutter")) {
    const json& s = j["shutter"];
    if (!s.is_array() || s.size() != 2)
      r.fail(p + "/shutter", "expected [open, close] in seconds, got " + r.type_of(s));
    c.shutter_open = r.number(s[0], p + "/shutter/0");
    c.shutter_close = r.number(s[1], p + "/shutter/1");
    if (!(c.shutter_open <= c.shutter_close))
      r.fail(p + "/shutter", "expected open <= close, got [" + format_number(c.shutter_open) +
                                 ", " + format_number(c.shutter_close) + "]");
  }
  read_lens(r, j, p, c);
  return c;
}

std::vector<camera_keyframe> read_keyframes(const scene_reader& r, const json& j,
                                            const std::string& p) {
  if (!j.is_array() || j.empty())
    r.fail(p, "expected a non-empty array of keyframes, got " + r.type_of(j));
  std::vector<camera_keyframe> keys;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const std::string kp = p + "/" + std::to_string(k);
    std::set<std::string> fields = pose_fields;
    fields.insert("time");
    r.only_fields(j[k], kp, fields);
    const double time = r.number(r.required(j[k], kp, "time"), kp + "/time");
    if (k > 0 && !(time > keys.back().time))
      r.fail(kp + "/time", "expected a time after the previous keyframe's " +
                               format_number(keys.back().time) + ", got " + format_number(time));
    keys.push_back({time, read_pose(r, j[k], kp)});
  }
  return keys;
}

// A camera: a pose, optionally turning ("orbit"), or a list of keyframes instead of a pose.
camera_path read_camera(const scene_reader& r, const json& j, const std::string& p) {
  std::set<std::string> fields = pose_fields;
  fields.insert({"orbit", "keyframes"});
  r.only_fields(j, p, fields);
  camera_path path;
  if (j.contains("keyframes")) {
    for (const auto& [key, value] : j.items())
      if (key != "keyframes")
        r.fail(p + "/" + key, "a camera with keyframes takes its pose from them; move \"" + key +
                                  "\" into the keyframes");
    path.motion = camera_motion::keyframes;
    path.keyframes = read_keyframes(r, j["keyframes"], p + "/keyframes");
  } else {
    path.pose = read_pose(r, j, p);
    if (j.contains("orbit")) {
      const json& o = j["orbit"];
      r.only_fields(o, p + "/orbit", {"period"});
      path.motion = camera_motion::orbit;
      path.orbit_period = r.number(r.required(o, p + "/orbit", "period"), p + "/orbit/period");
      if (path.orbit_period <= 0)
        r.fail(p + "/orbit/period",
               "expected seconds per turn > 0, got " + format_number(path.orbit_period));
    }
  }
  try {
    check_camera_path(path);
  } catch (const std::invalid_argument& e) {
    r.fail(p, e.what());
  }
  return path;
}

std::vector<named_camera> cameras_of(const scene_reader& r, const json& root) {
  if (root.contains("camera") && root.contains("cameras"))
    r.fail("/cameras", "a scene has either \"camera\" (one) or \"cameras\" (named), not both");
  if (root.contains("camera")) return {{"default", read_camera(r, root["camera"], "/camera")}};
  if (!root.contains("cameras")) return {{"default", {}}};
  const json& j = root["cameras"];
  if (!j.is_object() || j.empty())
    r.fail("/cameras", "expected an object of named cameras, got " +
                           (j.is_object() ? std::string("an empty one") : r.type_of(j)));
  std::vector<named_camera> cams;
  for (const auto& [name, value] : j.items()) {
    const std::string p = "/cameras/" + escape_pointer(name);
    if (!valid_camera_name(name))
      r.fail(p,
             "camera names may use letters, digits, '-', '_' and '.' (not first), at most 64 "
             "characters, and not \"all\"");
    cams.push_back({name, read_camera(r, value, p)});
  }
  return cams;
}

json pose_json(const camera_pose& c) {
  json j = {{"lookfrom", vec_json(c.lookfrom)}, {"lookat", vec_json(c.lookat)},
            {"vup", vec_json(c.vup)},           {"vfov", c.vfov},
            {"aperture", c.aperture},           {"focus_dist", c.focus_dist}};
  // The lesson's model is left unsaid, so scenes without projections dump as they always did.
  if (c.projection != projection::perspective)
    j["projection"] = std::string(projection_name(c.projection));
  if (c.fisheye_fov != camera_pose{}.fisheye_fov) j["fisheye_fov"] = c.fisheye_fov;
  if (c.shutter_open != 0 || c.shutter_close != 0)
    j["shutter"] = json::array({c.shutter_open, c.shutter_close});
  const lens_intrinsics& l = c.intrinsics;
  if (l.fx != 0 || l.fy != 0 || l.cx != 0 || l.cy != 0)
    j["intrinsics"] = json::array({l.fx, l.fy, l.cx, l.cy});
  std::size_t used = l.k.size();  // the coefficients up to the last nonzero one
  while (used > 0 && l.k[used - 1] == 0) --used;
  if (used > 0) j["distortion"] = json(std::vector<double>(l.k.begin(), l.k.begin() + used));
  if (l.width != 0 || l.height != 0) j["calibration_size"] = json::array({l.width, l.height});
  if (l.radius != 0) j["image_circle"] = l.radius;
  if (c.readout != 0)
    j["rolling_shutter"] = {{"direction", c.readout > 0 ? "top-down" : "bottom-up"},
                            {"readout", std::abs(c.readout)}};
  return j;
}

json camera_json(const camera_path& path) {
  if (path.motion == camera_motion::keyframes) {
    json keys = json::array();
    for (const camera_keyframe& k : path.keyframes) {
      json key = {{"time", k.time}};
      key.update(pose_json(k.pose));
      keys.push_back(key);
    }
    return {{"keyframes", keys}};
  }
  json j = pose_json(path.pose);
  if (path.motion == camera_motion::orbit) j["orbit"] = {{"period", path.orbit_period}};
  return j;
}

}  // namespace

void read_cameras(const scene_reader& r, const json& root, scene& s) {
  s.cameras = cameras_of(r, root);
}

void write_cameras(const scene& s, json& root) {
  if (s.cameras.size() == 1 && s.cameras[0].name == "default") {
    root["camera"] = camera_json(s.cameras[0].path);
  } else {
    json cams = json::object();
    for (const named_camera& c : s.cameras) cams[c.name] = camera_json(c.path);
    root["cameras"] = cams;
  }
}

}  // namespace rtvk::scene_json

namespace rtvk {

std::string dump_camera_json(const camera_pose& pose) {
  return scene_json::pose_json(pose).dump();
}

}  // namespace rtvk
