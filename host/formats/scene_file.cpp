#include "scene_file.h"

#include "object_group.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "camera_lens.h"
#include "errors.h"
#include "format.h"
#include "input_file.h"
#include "light_sources.h"
#include "mesh_file.h"
#include "parse_values.h"

namespace rtvk {
namespace {

using json = nlohmann::ordered_json;

// Walks a parsed document, checking each value against what the format expects. Every failure
// names the file and the JSON path (RFC 6901) of the offending value.
class scene_reader {
 public:
  explicit scene_reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw usage_error(file_ + ": " + (path.empty() ? "/" : path) + ": " + what);
  }

  void only_fields(const json& obj, const std::string& path,
                   const std::set<std::string>& allowed) const {
    if (!obj.is_object()) fail(path, "expected an object, got " + type_of(obj));
    for (const auto& [key, value] : obj.items())
      if (!allowed.count(key)) fail(path + "/" + key, "unknown field");
  }

  const json& required(const json& obj, const std::string& path, const std::string& key) const {
    if (!obj.contains(key)) fail(path, "missing field \"" + key + "\"");
    return obj[key];
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, "expected a number, got " + type_of(j));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "expected a finite number, got " + format_number(v));
    return v;
  }

  double number_in(const json& j, const std::string& path, double lo, double hi) const {
    const double v = number(j, path);
    if (v < lo || v > hi)
      fail(path, "expected a number in [" + format_number(lo) + ", " + format_number(hi) +
                     "], got " + format_number(v));
    return v;
  }

  long long integer(const json& j, const std::string& path, long long lo, long long hi) const {
    if (!j.is_number_integer())
      fail(path, "expected an integer, got " + (j.is_number() ? j.dump() : type_of(j)));
    const long long v = j.is_number_unsigned()
                            ? (long long)std::min<std::uint64_t>(j.get<std::uint64_t>(), 1ull << 62)
                            : j.get<long long>();
    if (v < lo || v > hi)
      fail(path, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "], got " + j.dump());
    return v;
  }

  vec3 vector3(const json& j, const std::string& path) const {
    if (!j.is_array() || j.size() != 3)
      fail(path, "expected an array of 3 numbers, got " + type_of(j));
    return vec3(number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2"));
  }

  color albedo(const json& j, const std::string& path) const {
    const vec3 c = vector3(j, path);
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0 || c[k] > 1)
        fail(path + "/" + std::to_string(k),
             "expected an albedo in [0, 1], got " + format_number(c[k]));
    return c;
  }

  color radiance(const json& j, const std::string& path) const {
    const vec3 c = vector3(j, path);
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0)
        fail(path + "/" + std::to_string(k), "expected a color >= 0, got " + format_number(c[k]));
    return c;
  }

  static std::string type_of(const json& j) {
    if (j.is_number()) return "a number";
    return std::string(j.is_array() || j.is_object() ? "an " : "a ") + j.type_name();
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;  // named in every message

 public:
  // Images already decoded for this file, by the path read: a scene naming one image in many
  // textures holds and uploads its texels once.
  mutable std::map<std::string, std::shared_ptr<const texel_image>> images;
};

std::string escape_pointer(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

const std::set<std::string> pose_fields = {
    "lookfrom",   "lookat",           "vup",          "vfov",           "aperture",
    "focus_dist", "projection",       "fisheye_fov",  "shutter",        "intrinsics",
    "distortion", "calibration_size", "image_circle", "rolling_shutter"};

// The calibrated models' fields (docs/scene-format.md): intrinsics, distortion, the size they
// were calibrated at, the polynomial fisheye's image circle, and the rolling shutter. What the
// camera would refuse of them is refused here, at the field.
void read_lens(const scene_reader& r, const json& j, const std::string& p, camera_pose& c) {
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
  if (j.contains("rolling_shutter")) {
    const json& s = j["rolling_shutter"];
    const std::string sp = p + "/rolling_shutter";
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
    c.readout = top_down ? readout : -readout;
  }
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

std::vector<named_camera> read_cameras(const scene_reader& r, const json& root) {
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

// An optional true or false field (default false).
bool read_flag(const scene_reader& r, const json& j, const std::string& p, const char* key) {
  if (!j.contains(key)) return false;
  if (!j[key].is_boolean())
    r.fail(p + "/" + key, "expected true or false, got " + r.type_of(j[key]));
  return j[key].get<bool>();
}

render_settings read_render(const scene_reader& r, const json& j) {
  const std::string p = "/render";
  r.only_fields(j, p,
                {"width", "aspect", "spp", "max_depth", "seed", "gamma", "jitter", "sampling"});
  render_settings s;
  if (j.contains("width")) s.width = int(r.integer(j["width"], p + "/width", 1, max_image_side));
  if (j.contains("aspect")) {
    const json& a = j["aspect"];
    if (a.is_string()) {
      s.aspect = parse_aspect(a.get<std::string>(), r.file() + ": " + p + "/aspect");
    } else {
      s.aspect = r.number(a, p + "/aspect");
      if (s.aspect <= 0) r.fail(p + "/aspect", "expected a number > 0, got " + a.dump());
    }
  }
  if (j.contains("spp")) s.spp = int(r.integer(j["spp"], p + "/spp", 1, max_spp));
  if (j.contains("max_depth"))
    s.max_depth = int(r.integer(j["max_depth"], p + "/max_depth", 1, max_depth_limit));
  if (j.contains("seed"))
    s.seed = std::uint32_t(r.integer(j["seed"], p + "/seed", 0, 0xffffffffll));
  if (j.contains("gamma")) s.gamma = r.number_in(j["gamma"], p + "/gamma", 0.1, 10);
  if (j.contains("jitter")) {
    if (!j["jitter"].is_boolean())
      r.fail(p + "/jitter", "expected true or false, got " + r.type_of(j["jitter"]));
    s.jitter = j["jitter"].get<bool>();
  }
  if (j.contains("sampling")) {
    const json& m = j["sampling"];
    const std::string name = m.is_string() ? m.get<std::string>() : "";
    if (name == "plain")
      s.sampling = sampling_mode::plain;
    else if (name == "lights")
      s.sampling = sampling_mode::lights;
    else if (name == "auto")
      s.sampling = sampling_mode::automatic;
    else
      r.fail(p + "/sampling", "expected \"plain\", \"lights\" or \"auto\", got " + m.dump());
  }
  return s;
}

// A noise style's name.
noise_style read_style(const scene_reader& r, const json& j, const std::string& p) {
  for (noise_style st : {noise_style::smooth, noise_style::turbulence, noise_style::marble})
    if (j.is_string() && j.get<std::string>() == style_name(st)) return st;
  r.fail(p, "expected \"smooth\", \"turbulence\" or \"marble\", got " +
                (j.is_string() ? "\"" + j.get<std::string>() + "\"" : r.type_of(j)));
}

// An image's wrap mode's name.
image_wrap read_wrap(const scene_reader& r, const json& j, const std::string& p) {
  for (image_wrap w : {image_wrap::clamp, image_wrap::repeat, image_wrap::mirror})
    if (j.is_string() && j.get<std::string>() == wrap_name(w)) return w;
  r.fail(p, "expected \"clamp\", \"repeat\" or \"mirror\", got " +
                (j.is_string() ? "\"" + j.get<std::string>() + "\"" : r.type_of(j)));
}

// A color field that may be a texture instead: a color (in [0, 1], or any value >= 0 for a lamp's
// `emit`), or a texture object ({"type": "checker" | "image" | "noise" | "solid", ...}), which is
// appended to s.textures. Sets m.albedo or m.texture.
void read_color_or_texture(const scene_reader& r, const json& j, const std::string& p,
                           bool radiance, const std::filesystem::path& base, scene& s,
                           material& m) {
  // A color of this field's kind: a lamp's radiance (>= 0) or an albedo (in [0, 1]).
  const auto color_at = [&](const json& c, const std::string& at) {
    return radiance ? r.radiance(c, at) : r.albedo(c, at);
  };
  if (!j.is_object()) {
    m.albedo = color_at(j, p);
    return;
  }
  const json& type = r.required(j, p, "type");
  const std::string t = type.is_string() ? type.get<std::string>() : "";
  texture tex;
  if (t == "solid") {
    r.only_fields(j, p, {"type", "color"});
    const json& c = r.required(j, p, "color");
    m.albedo = color_at(c, p + "/color");
    return;
  } else if (t == "checker") {
    r.only_fields(j, p, {"type", "scale", "even", "odd"});
    tex.type = texture_type::checker;
    tex.even = color_at(r.required(j, p, "even"), p + "/even");
    tex.odd = color_at(r.required(j, p, "odd"), p + "/odd");
  } else if (t == "noise") {
    r.only_fields(j, p, {"type", "scale", "style", "color"});
    tex.type = texture_type::noise;
    if (j.contains("style")) tex.style = read_style(r, j["style"], p + "/style");
    if (j.contains("color")) tex.even = color_at(j["color"], p + "/color");
  } else if (t == "image") {
    r.only_fields(j, p, {"type", "file", "color", "wrap"});
    tex.type = texture_type::image;
    if (j.contains("color")) tex.even = color_at(j["color"], p + "/color");
    if (j.contains("wrap")) {  // one mode for both axes, or [u's, v's]
      const json& w = j["wrap"];
      if (w.is_array() && w.size() == 2) {
        tex.wrap_u = read_wrap(r, w[0], p + "/wrap/0");
        tex.wrap_v = read_wrap(r, w[1], p + "/wrap/1");
      } else {
        tex.wrap_u = tex.wrap_v = read_wrap(r, w, p + "/wrap");
      }
    }
    const json& f = r.required(j, p, "file");
    if (!f.is_string() || f.get<std::string>().empty())
      r.fail(p + "/file", "expected a file name, got " + r.type_of(f));
    tex.file = f.get<std::string>();
    const std::string field = r.file() + ": " + p + "/file";
    const std::size_t hash = tex.file.rfind("#images/");
    std::shared_ptr<const texel_image>& cached = r.images[tex.file];
    if (cached) {
      tex.image = cached;
    } else if (tex.file == builtin_planet) {
      tex.image = planet_image(1024, 512, 0);
    } else if (hash != std::string::npos && !mesh_kind(tex.file.substr(0, hash)).empty()) {
      // A glTF's embedded image, as rtvk scene dump names a mesh's base color texture.
      const std::string n = tex.file.substr(hash + 8);
      if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos)
        r.fail(p + "/file", "expected FILE#images/N, got \"" + tex.file + "\"");
      tex.image = gltf_image(base / tex.file.substr(0, hash), std::stoul(n), field);
    } else {
      tex.image = load_texel_image(base / tex.file, field);
    }
    cached = tex.image;
    std::uint64_t texels = 0;
    for (const auto& [name, image] : r.images)
      if (image) texels += image->texels.size();
    if (texels > max_scene_texels)
      r.fail(p + "/file", "the scene's images hold " + std::to_string(texels) +
                              " texels, past the limit of " + std::to_string(max_scene_texels));
  } else {
    r.fail(p + "/type", "unknown texture type " +
                            (type.is_string() ? "\"" + t + "\"" : r.type_of(type)) +
                            " (expected solid, checker, image or noise)");
  }
  // Scales float keeps (its 1 / scale too): the GPU reads them in float.
  if (j.contains("scale")) tex.scale = r.number_in(j["scale"], p + "/scale", 1e-6, 1e6);
  if (s.textures.size() >= 1000000) r.fail(p, "more than a million textures");
  m.texture = int(s.textures.size());
  s.textures.push_back(std::move(tex));
}

material read_material(const scene_reader& r, const json& j, const std::string& p,
                       const std::filesystem::path& base, scene& s) {
  if (!j.is_object()) r.fail(p, "expected an object, got " + r.type_of(j));
  const json& type = r.required(j, p, "type");
  if (!type.is_string()) r.fail(p + "/type", "expected a string, got " + r.type_of(type));
  const std::string t = type.get<std::string>();
  const std::optional<material_kind> kind = kind_named(t);
  if (!kind)
    r.fail(p + "/type", "unknown material type \"" + t + "\" (expected " + kind_names() + ")");
  // A lamp's color is what it emits (the book's `emit`, any strength); the others' what they keep.
  const bool lamp = kind->type == material_type::diffuse_light;
  const std::string color_field = lamp ? "emit" : "albedo";
  std::set<std::string> fields{"type"};
  if (kind->albedo) fields.insert(color_field);
  if (kind->fuzz) fields.insert("fuzz");
  if (kind->ir) fields.insert("ir");
  if (lamp) fields.insert("one_sided");
  r.only_fields(j, p, fields);
  material m;
  m.type = kind->type;
  if (kind->albedo)
    read_color_or_texture(r, r.required(j, p, color_field), p + "/" + color_field, lamp, base, s,
                          m);
  if (kind->fuzz && j.contains("fuzz")) m.fuzz = r.number_in(j["fuzz"], p + "/fuzz", 0, 1);
  m.one_sided = lamp && read_flag(r, j, p, "one_sided");
  if (kind->ir) {
    m.ir = r.number(r.required(j, p, "ir"), p + "/ir");
    if (m.ir <= 0)
      r.fail(p + "/ir", "expected an index of refraction > 0, got " + format_number(m.ir));
  }
  return m;
}

sky read_sky(const scene_reader& r, const json& j) {
  r.only_fields(j, "/sky", {"horizon", "zenith"});
  sky out;
  if (j.contains("horizon")) out.horizon = r.radiance(j["horizon"], "/sky/horizon");
  if (j.contains("zenith")) out.zenith = r.radiance(j["zenith"], "/sky/zenith");
  return out;
}

// Fills s.materials from /materials, in the file's order; returns each name's index there.
std::map<std::string, int> read_materials(const scene_reader& r, const json& mats,
                                          const std::filesystem::path& base, scene& s) {
  if (!mats.is_object())
    r.fail("/materials", "expected an object of named materials, got " + r.type_of(mats));
  std::map<std::string, int> index;
  for (const auto& [key, value] : mats.items()) {
    index[key] = int(s.materials.size());
    material m = read_material(r, value, "/materials/" + escape_pointer(key), base, s);
    s.materials.push_back({key, m});
  }
  return index;
}

// The index of the material a field names (`material_index` maps names to scene indices).
int material_named(const scene_reader& r, const json& j, const std::string& p,
                   const std::map<std::string, int>& material_index) {
  const json& m = r.required(j, p, "material");
  if (!m.is_string()) r.fail(p + "/material", "expected a material name, got " + r.type_of(m));
  const auto found = material_index.find(m.get<std::string>());
  if (found == material_index.end())
    r.fail(p + "/material", "no material named \"" + m.get<std::string>() + "\" in /materials");
  return found->second;
}

// An object's placement: {"scale": s or [x, y, z], "rotate": {"axis": [x, y, z], "degrees": d},
// "translate": [x, y, z]}, each optional, applied in that order.
// A placement as a matrix: 12 numbers (3 rows of x, y, z, translation) or 16 (a 4x4 whose last
// row must be 0 0 0 1), row-major, as exporters write a node's world matrix.
transform read_matrix(const scene_reader& r, const json& m, const std::string& p) {
  if (!m.is_array() || (m.size() != 12 && m.size() != 16))
    r.fail(p, "expected 12 or 16 numbers (row-major), got " +
                  (m.is_array() ? std::to_string(m.size()) + " values" : r.type_of(m)));
  double v[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
  for (std::size_t k = 0; k < m.size(); ++k) v[k] = r.number(m[k], p + "/" + std::to_string(k));
  if (v[12] != 0 || v[13] != 0 || v[14] != 0 || v[15] != 1)
    r.fail(p, "the last row must be 0 0 0 1 (an affine placement, no projection)");
  transform t;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) t.linear[col][row] = v[4 * row + col];
    t.offset[row] = v[4 * row + 3];
  }
  return t;
}

transform read_transform(const scene_reader& r, const json& j, const std::string& p) {
  r.only_fields(j, p, {"scale", "rotate", "translate", "matrix"});
  if (j.contains("matrix")) {
    for (const char* other : {"scale", "rotate", "translate"})
      if (j.contains(other))
        r.fail(p + "/" + other, "a transform is a matrix or scale, rotate and translate, not both");
    const transform t = read_matrix(r, j["matrix"], p + "/matrix");
    if (const std::optional<std::string> why = degenerate(t))
      r.fail(p, "the transform cannot place anything: " + *why);
    return t;
  }
  vec3 scale(1), axis(0, 1, 0), offset(0);
  double degrees = 0;
  if (j.contains("scale")) {
    const json& sc = j["scale"];
    scale = sc.is_number() ? vec3(r.number(sc, p + "/scale")) : r.vector3(sc, p + "/scale");
  }
  if (j.contains("rotate")) {
    const std::string rp = p + "/rotate";
    r.only_fields(j["rotate"], rp, {"axis", "degrees"});
    axis = r.vector3(r.required(j["rotate"], rp, "axis"), rp + "/axis");
    if (!(glm::length(axis) > 0) || !std::isfinite(glm::length(axis)))
      r.fail(rp + "/axis", "expected a nonzero finite axis");
    degrees = r.number(r.required(j["rotate"], rp, "degrees"), rp + "/degrees");
  }
  if (j.contains("translate")) offset = r.vector3(j["translate"], p + "/translate");
  const transform t = make_transform(scale, axis, degrees, offset);
  if (const std::optional<std::string> why = degenerate(t))
    r.fail(p, "the transform cannot place anything: " + *why);
  return t;
}

transform optional_transform(const scene_reader& r, const json& j, const std::string& p) {
  return j.contains("transform") ? read_transform(r, j["transform"], p + "/transform")
                                 : transform{};
}

// The array field `key` of `root` (empty when absent), each element read by `read`; `at` is
// where `root` is in the file (a JSON pointer; "" for the file's root).
template <typename Read>
void read_array(const scene_reader& r, const json& root, const std::string& at,
                const std::string& key, Read read) {
  if (!root.contains(key)) return;
  const json& items = root[key];
  if (!items.is_array()) r.fail(at + "/" + key, "expected an array, got " + r.type_of(items));
  for (std::size_t i = 0; i < items.size(); ++i)
    read(items[i], at + "/" + key + "/" + std::to_string(i));
}

// Quads, boxes and triangles, each placed by its optional transform.
void read_flat_objects(const scene_reader& r, const json& root, const std::string& at,
                       const std::map<std::string, int>& material_index, scene& s) {
  read_array(r, root, at, "quads", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"Q", "u", "v", "material", "transform", "sample"});
    quad q;
    q.sampled = read_flag(r, j, p, "sample");
    q.Q = r.vector3(r.required(j, p, "Q"), p + "/Q");
    q.u = r.vector3(r.required(j, p, "u"), p + "/u");
    q.v = r.vector3(r.required(j, p, "v"), p + "/v");
    q = placed(q, optional_transform(r, j, p));
    if (!spans_area(q.u, q.v)) r.fail(p, "u and v are parallel (or zero): the quad has no area");
    q.material = material_named(r, j, p, material_index);
    s.quads.push_back(q);
  });
  read_array(r, root, at, "boxes", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"a", "b", "material", "transform"});
    const point3 a = r.vector3(r.required(j, p, "a"), p + "/a");
    const point3 b = r.vector3(r.required(j, p, "b"), p + "/b");
    for (int k = 0; k < 3; ++k)
      if (a[k] == b[k])
        r.fail(p + "/b/" + std::to_string(k), "the box is flat: a and b share this coordinate");
    add_box(s, a, b, material_named(r, j, p, material_index), optional_transform(r, j, p));
    // Each side as a quad file would have to read it (a dump writes them so): a side too thin or
    // too large for its normal in float has no area to hit.
    for (std::size_t k = s.quads.size() - 6; k < s.quads.size(); ++k)
      if (!spans_area(s.quads[k].u, s.quads[k].v))
        r.fail(p, "side " + std::to_string(k + 6 - s.quads.size()) +
                      " of the box has no area in float (too thin or too large)");
  });
  read_array(r, root, at, "triangles", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"vertices", "normals", "uv", "material", "transform"});
    const transform t = optional_transform(r, j, p);
    const auto three = [&](const std::string& key) {
      const json& v = r.required(j, p, key);
      if (!v.is_array() || v.size() != 3)
        r.fail(p + "/" + key, "expected an array of 3 points, got " + r.type_of(v));
      return std::array<vec3, 3>{r.vector3(v[0], p + "/" + key + "/0"),
                                 r.vector3(v[1], p + "/" + key + "/1"),
                                 r.vector3(v[2], p + "/" + key + "/2")};
    };
    triangle tri;
    tri.p = three("vertices");
    tri = placed(tri, t);
    tri.material = material_named(r, j, p, material_index);
    if (!has_area(tri.p)) r.fail(p + "/vertices", "the vertices are collinear: no area");
    if (j.contains("normals") || j.contains("uv")) {
      triangle_shading sh;
      if (j.contains("normals")) {
        sh.normal = three("normals");
        for (std::size_t k = 0; k < 3; ++k)
          if (!(glm::length(sh.normal[k]) > 0) || !std::isfinite(glm::length(sh.normal[k])))
            r.fail(p + "/normals/" + std::to_string(k), "expected a nonzero normal");
      }
      if (j.contains("uv")) {  // texture coordinates, a pair per vertex
        const json& uv = j["uv"];
        if (!uv.is_array() || uv.size() != 3)
          r.fail(p + "/uv", "expected an array of 3 [u, v] pairs, got " + r.type_of(uv));
        for (std::size_t k = 0; k < 3; ++k) {
          const std::string at = p + "/uv/" + std::to_string(k);
          if (!uv[k].is_array() || uv[k].size() != 2)
            r.fail(at, "expected [u, v], got " + r.type_of(uv[k]));
          sh.uv[k] = glm::dvec2(r.number_in(uv[k][0], at + "/0", -1e6, 1e6),
                                r.number_in(uv[k][1], at + "/1", -1e6, 1e6));
        }
        sh.has_uv = true;
      }
      // As written when nothing places the triangle (so a dump reads back unchanged); the
      // renderers normalize them.
      tri.shading = std::int32_t(s.shading.size());
      s.shading.push_back(placed(sh, t));
    }
    s.triangles.push_back(tri);
  });
}

// Mesh files, each named relative to the scene file (`base`), with a material of the scene's
// (or the file's own) and a placement.
void read_meshes(const scene_reader& r, const json& root, const std::string& at,
                 const std::filesystem::path& base,
                 const std::map<std::string, int>& material_index, scene& s) {
  read_array(r, root, at, "meshes", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"file", "material", "transform"});
    const json& f = r.required(j, p, "file");
    if (!f.is_string() || f.get<std::string>().empty())
      r.fail(p + "/file", "expected a mesh file name, got " + r.type_of(f));
    mesh_placement how;
    how.placement = optional_transform(r, j, p);
    if (j.contains("material")) how.material = material_named(r, j, p, material_index);
    const std::filesystem::path file = base / f.get<std::string>();
    if (mesh_kind(file).empty())
      r.fail(p + "/file", "\"" + f.get<std::string>() + "\" is not .obj, .gltf or .glb");
    load_mesh(s, file, how);
  });
}

// `material_index` maps a material name to its index in the scene.
sphere read_sphere(const scene_reader& r, const json& j, const std::string& p,
                   const std::map<std::string, int>& material_index) {
  r.only_fields(j, p, {"center", "center1", "radius", "material", "transform", "sample"});
  sphere sp;
  sp.sampled = read_flag(r, j, p, "sample");
  sp.center = r.vector3(r.required(j, p, "center"), p + "/center");
  // A moving sphere: at "center" at time 0 and "center1" at time 1, linear before and after.
  if (j.contains("center1")) sp.center1 = r.vector3(j["center1"], p + "/center1");
  sp.radius = r.number(r.required(j, p, "radius"), p + "/radius");
  if (sp.radius <= 0)
    r.fail(p + "/radius", "expected a radius > 0, got " + format_number(sp.radius));
  if (j.contains("transform")) {
    // A sphere stays a sphere under a rotation and one scale; a non-uniform scale would make an
    // ellipsoid, which needs object-space instances (docs/geometry.md).
    const std::optional<sphere> moved =
        placed(sp, read_transform(r, j["transform"], p + "/transform"));
    if (!moved)
      r.fail(
          p + "/transform",
          "a sphere can be scaled only uniformly (an ellipsoid is a group placed by an instance)");
    sp = *moved;
  }
  sp.material = material_named(r, j, p, material_index);
  return sp;
}

std::vector<sphere> read_spheres(const scene_reader& r, const json& root, const std::string& at,
                                 const std::map<std::string, int>& material_index) {
  std::vector<sphere> out;
  read_array(r, root, at, "spheres", [&](const json& j, const std::string& p) {
    out.push_back(read_sphere(r, j, p, material_index));
  });
  return out;
}

// The groups instances place, by name: each read as the objects of a scene (spheres, quads,
// boxes, triangles, meshes) with the scene's materials; a mesh file's own materials are added
// to the scene's.
void read_groups(const scene_reader& r, const json& groups, const std::filesystem::path& base,
                 const std::map<std::string, int>& material_index, scene& s) {
  if (!groups.is_object())
    r.fail("/groups", "expected an object of named groups, got " + r.type_of(groups));
  for (const auto& [name, j] : groups.items()) {
    const std::string p = "/groups/" + escape_pointer(name);
    if (!j.is_object()) r.fail(p, "expected an object, got " + r.type_of(j));
    r.only_fields(j, p, {"spheres", "quads", "boxes", "triangles", "meshes"});
    scene g;
    g.materials = std::move(s.materials);
    g.spheres = read_spheres(r, j, p, material_index);
    read_flat_objects(r, j, p, material_index, g);
    read_meshes(r, j, p, base, material_index, g);
    s.materials = std::move(g.materials);
    for (std::size_t k = 0; k < g.spheres.size(); ++k)
      if (g.spheres[k].center1)
        r.fail(p + "/spheres/" + std::to_string(k) + "/center1",
               "a group's spheres cannot move (instances place still objects)");
    for (std::size_t k = 0; k < g.spheres.size(); ++k)
      if (g.spheres[k].sampled)
        r.fail(p + "/spheres/" + std::to_string(k) + "/sample",
               "lights sampling aims only at the scene's own objects, not a group's");
    for (std::size_t k = 0; k < g.quads.size(); ++k)
      if (g.quads[k].sampled)
        r.fail(p + "/quads/" + std::to_string(k) + "/sample",
               "lights sampling aims only at the scene's own objects, not a group's");
    object_group group{name,          std::move(g.spheres), std::move(g.quads),
                       std::move(g.triangles), std::move(g.shading), std::move(g.disks)};
    if (empty(group)) r.fail(p, "the group has no object (nothing an instance could place)");
    s.groups.push_back(std::move(group));
  }
}

// Each instance: a group and its placement.
void read_instances(const scene_reader& r, const json& root, scene& s) {
  read_array(r, root, "", "instances", [&](const json& j, const std::string& p) {
    r.only_fields(j, p, {"group", "transform"});
    const json& name = r.required(j, p, "group");
    const auto found = std::find_if(s.groups.begin(), s.groups.end(), [&](const object_group& g) {
      return name.is_string() && g.name == name.get<std::string>();
    });
    if (found == s.groups.end()) {
      std::string known;
      for (const object_group& g : s.groups) known += (known.empty() ? "" : ", ") + g.name;
      r.fail(p + "/group",
             "expected the name of a group (" +
                 (known.empty() ? std::string("the scene has none") : known) + "), got " +
                 (name.is_string() ? "\"" + name.get<std::string>() + "\"" : r.type_of(name)));
    }
    if (s.instances.size() >= std::size_t(RTVK_LEAF_INDEX_MASK))
      r.fail(p, "more than " + std::to_string(std::size_t(RTVK_LEAF_INDEX_MASK)) +
                    " instances (a BVH leaf reference's 28 bits, less one)");
    s.instances.push_back({std::uint32_t(found - s.groups.begin()), optional_transform(r, j, p)});
  });
}

// /media: the book's constant_medium, a sphere ({"shape": "sphere", "center", "radius"}) or a
// box ({"shape": "box", "a", "b", "transform"}) of fog, {"density", "material"} (isotropic).
void read_media(const scene_reader& r, const json& root,
                const std::map<std::string, int>& material_index, scene& s) {
  read_array(r, root, "", "media", [&](const json& j, const std::string& p) {
    const json& shape = r.required(j, p, "shape");
    const std::string sh = shape.is_string() ? shape.get<std::string>() : "";
    medium m;
    if (sh == "sphere") {
      r.only_fields(j, p, {"shape", "center", "radius", "density", "material"});
      m.shape = boundary_shape::sphere;
      m.center = r.vector3(r.required(j, p, "center"), p + "/center");
      m.radius = r.number(r.required(j, p, "radius"), p + "/radius");
      if (!(m.radius > 0))
        r.fail(p + "/radius", "expected a radius > 0, got " + format_number(m.radius));
    } else if (sh == "box") {
      r.only_fields(j, p, {"shape", "a", "b", "transform", "density", "material"});
      m.shape = boundary_shape::box;
      const point3 a = r.vector3(r.required(j, p, "a"), p + "/a");
      const point3 b = r.vector3(r.required(j, p, "b"), p + "/b");
      for (int k = 0; k < 3; ++k)
        if (a[k] == b[k])
          r.fail(p + "/b/" + std::to_string(k), "the box is flat: a and b share this coordinate");
      m.lo = glm::min(a, b);
      m.hi = glm::max(a, b);
      m.placement = optional_transform(r, j, p);
    } else {
      r.fail(p + "/shape", "expected \"sphere\" or \"box\", got " +
                               (shape.is_string() ? "\"" + sh + "\"" : r.type_of(shape)));
    }
    m.density = r.number(r.required(j, p, "density"), p + "/density");
    if (!(m.density > 0))
      r.fail(p + "/density", "expected a density > 0, got " + format_number(m.density));
    m.material = material_named(r, j, p, material_index);
    if (s.materials[std::size_t(m.material)].m.type != material_type::isotropic)
      r.fail(p + "/material", "a medium scatters by an isotropic material, \"" +
                                  s.materials[std::size_t(m.material)].name + "\" is " +
                                  type_name(s.materials[std::size_t(m.material)].m.type));
    if (s.media.size() >= max_scene_media)
      r.fail(p, "more than " + std::to_string(max_scene_media) + " media");
    s.media.push_back(m);
  });
}

scene read_scene(const scene_reader& r, const json& root, const std::string& name,
                 const std::filesystem::path& base) {
  r.only_fields(
      root, "",
      {"camera", "cameras", "render", "sky", "background", "materials", "spheres", "quads", "boxes",
       "triangles", "meshes", "groups", "instances", "media", "noise_seed"});
  scene s;
  s.name = name;
  s.cameras = read_cameras(r, root);
  if (root.contains("render")) s.render = read_render(r, root["render"]);
  if (root.contains("sky")) s.sky = read_sky(r, root["sky"]);
  if (root.contains("background")) {  // the second book's constant color: a uniform sky
    if (root.contains("sky")) r.fail("/background", "a scene has a sky or a background, not both");
    s.sky.horizon = s.sky.zenith = r.radiance(root["background"], "/background");
  }
  std::map<std::string, int> material_index;
  if (root.contains("noise_seed"))
    s.noise_seed = std::uint32_t(r.integer(root["noise_seed"], "/noise_seed", 0, 0xffffffffll));
  if (root.contains("materials")) material_index = read_materials(r, root["materials"], base, s);
  s.spheres = read_spheres(r, root, "", material_index);
  read_flat_objects(r, root, "", material_index, s);
  read_meshes(r, root, "", base, material_index, s);
  if (root.contains("groups") || root.contains("instances")) {
    if (root.contains("groups")) read_groups(r, root["groups"], base, material_index, s);
    read_instances(r, root, s);
  }
  read_media(r, root, material_index, s);
  if (!root.contains("spheres") && object_count(s) == 0 && !root.contains("meshes") &&
      !root.contains("instances") && s.media.empty())
    r.fail("",
           "missing field \"spheres\" (a scene needs spheres, quads, boxes, triangles, meshes "
           "or instances)");
  try {
    camera(camera_pose{}, s.render.aspect, s.render.width);  // the image size, alone
  } catch (const std::invalid_argument& e) {
    r.fail("/render", e.what());
  }
  return s;
}

json vec_json(const vec3& v) {
  return json::array({v.x, v.y, v.z});
}

// A placement as the 12 numbers read_matrix reads (row-major, translation last in each row).
json matrix_json(const transform& t) {
  json m = json::array();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) m.push_back(t.linear[col][row]);
    m.push_back(t.offset[row]);
  }
  return m;
}

json texture_json(const texture& t) {
  json j = {{"type", type_name(t.type)}};
  switch (t.type) {
    case texture_type::checker:
      j["scale"] = t.scale;
      j["even"] = vec_json(t.even);
      j["odd"] = vec_json(t.odd);
      break;
    case texture_type::noise:
      j["scale"] = t.scale;
      j["style"] = style_name(t.style);
      j["color"] = vec_json(t.even);
      break;
    case texture_type::image:
      j["file"] = t.file;
      if (t.even != color(1)) j["color"] = vec_json(t.even);
      if (t.wrap_u != t.wrap_v)
        j["wrap"] = json::array({wrap_name(t.wrap_u), wrap_name(t.wrap_v)});
      else if (t.wrap_u != image_wrap::clamp)
        j["wrap"] = wrap_name(t.wrap_u);
      break;
  }
  return j;
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

// Pretty-prints with anything that fits on one line kept on one line: a sphere or a vector
// reads as one line rather than ten.
void write_json(const json& j, int indent, std::string& out) {
  const std::string flat = j.dump();
  if (flat.size() + std::size_t(indent) <= 100 || !j.is_structured()) {
    out += flat;
    return;
  }
  const std::string pad(std::size_t(indent) + 2, ' ');
  const bool object = j.is_object();
  out += object ? "{\n" : "[\n";
  std::size_t i = 0;
  for (auto it = j.begin(); it != j.end(); ++it, ++i) {
    out += pad;
    if (object) out += json(it.key()).dump() + ": ";
    write_json(*it, indent + 2, out);
    out += i + 1 < j.size() ? ",\n" : "\n";
  }
  out += std::string(std::size_t(indent), ' ') + (object ? "}" : "]");
}

}  // namespace

scene parse_scene_json(const std::string& text, const std::string& file_name) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ..."
    // (numbers too large for a double, such as 1e999, come as out_of_range errors)
    std::string what = e.what();
    const auto start = what.find("] ");
    if (start != std::string::npos) what = what.substr(start + 2);
    throw usage_error(file_name + ": " + what);
  }
  const std::filesystem::path base = std::filesystem::path(file_name).parent_path();
  return read_scene(scene_reader(file_name), root, file_name, base.empty() ? "." : base);
}

scene load_scene_file(const std::filesystem::path& path) {
  const std::string text = read_regular_file(path, max_scene_file_bytes, "scene file");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw usage_error(path.string() + ": empty scene file");
  return parse_scene_json(text, path.string());
}

std::string dump_camera_json(const camera_pose& pose) {
  return pose_json(pose).dump();
}

namespace {

// The objects of the scene or of a group, as their fields: spheres always (a scene file's
// required field), quads and triangles where there are some.
void write_objects(json& root, const scene& s, const std::vector<sphere>& sphere_list,
                   const std::vector<quad>& quad_list, const std::vector<triangle>& triangle_list,
                   const std::vector<triangle_shading>& shading) {
  const auto material_name = [&](int m) { return s.materials[std::size_t(m)].name; };
  json spheres = json::array();
  for (const sphere& sp : sphere_list) {
    json j = {{"center", vec_json(sp.center)}};
    if (sp.center1) j["center1"] = vec_json(*sp.center1);
    j["radius"] = sp.radius;
    j["material"] = material_name(sp.material);
    if (sp.sampled) j["sample"] = true;
    spheres.push_back(j);
  }
  root["spheres"] = spheres;
  if (!quad_list.empty()) {
    json quads = json::array();
    for (const quad& q : quad_list) {
      json j = {{"Q", vec_json(q.Q)},
                {"u", vec_json(q.u)},
                {"v", vec_json(q.v)},
                {"material", material_name(q.material)}};
      if (q.sampled) j["sample"] = true;
      quads.push_back(j);
    }
    root["quads"] = quads;
  }
  if (!triangle_list.empty()) {
    json triangles = json::array();
    for (const triangle& t : triangle_list) {
      json j = {{"vertices", json::array({vec_json(t.p[0]), vec_json(t.p[1]), vec_json(t.p[2])})}};
      if (t.shading >= 0 && shading[std::size_t(t.shading)].has_normals()) {
        const auto& n = shading[std::size_t(t.shading)].normal;
        j["normals"] = json::array({vec_json(n[0]), vec_json(n[1]), vec_json(n[2])});
      }
      if (t.shading >= 0 && shading[std::size_t(t.shading)].has_uv) {
        json uv = json::array();
        for (const glm::dvec2& c : shading[std::size_t(t.shading)].uv)
          uv.push_back(json::array({c.x, c.y}));
        j["uv"] = uv;
      }
      j["material"] = material_name(t.material);
      triangles.push_back(j);
    }
    root["triangles"] = triangles;
  }
}

}  // namespace

std::string dump_scene_json(const scene& s) {
  json root;
  if (s.cameras.size() == 1 && s.cameras[0].name == "default") {
    root["camera"] = camera_json(s.cameras[0].path);
  } else {
    json cams = json::object();
    for (const named_camera& c : s.cameras) cams[c.name] = camera_json(c.path);
    root["cameras"] = cams;
  }
  const render_settings& r = s.render;
  root["render"] = {{"width", r.width},         {"aspect", r.aspect}, {"spp", r.spp},
                    {"max_depth", r.max_depth}, {"seed", r.seed},     {"gamma", r.gamma},
                    {"jitter", r.jitter}};
  if (r.sampling != sampling_mode::automatic)
    root["render"]["sampling"] = sampling_name(r.sampling);
  if (s.sky.horizon == s.sky.zenith)
    root["background"] = vec_json(s.sky.horizon);
  else
    root["sky"] = {{"horizon", vec_json(s.sky.horizon)}, {"zenith", vec_json(s.sky.zenith)}};
  if (s.noise_seed != 0) root["noise_seed"] = s.noise_seed;
  json mats = json::object();
  for (const auto& [name, m] : s.materials) {
    const material_kind& kind = kind_of(m.type);
    json j = {{"type", type_name(m.type)}};
    const std::string color_field = m.type == material_type::diffuse_light ? "emit" : "albedo";
    if (kind.albedo)
      j[color_field] =
          m.texture >= 0 ? texture_json(s.textures[std::size_t(m.texture)]) : vec_json(m.albedo);
    if (kind.fuzz) j["fuzz"] = m.fuzz;
    if (kind.ir) j["ir"] = m.ir;
    if (m.one_sided) j["one_sided"] = true;
    mats[name] = j;
  }
  root["materials"] = mats;
  write_objects(root, s, s.spheres, s.quads, s.triangles, s.shading);
  if (!s.groups.empty()) {
    json groups = json::object();
    for (const object_group& g : s.groups) {
      json objects = json::object();
      write_objects(objects, s, g.spheres, g.quads, g.triangles, g.shading);
      groups[g.name] = objects;
    }
    root["groups"] = groups;
    json instances = json::array();
    for (const instance& i : s.instances) {
      json j = {{"group", s.groups[i.group].name}};
      if (!i.placement.is_identity()) j["transform"] = {{"matrix", matrix_json(i.placement)}};
      instances.push_back(j);
    }
    root["instances"] = instances;
  }
  if (!s.media.empty()) {
    json media = json::array();
    for (const medium& m : s.media) {
      json j = {{"shape", shape_name(m.shape)}};
      if (m.shape == boundary_shape::sphere) {
        j["center"] = vec_json(m.center);
        j["radius"] = m.radius;
      } else {
        j["a"] = vec_json(m.lo);
        j["b"] = vec_json(m.hi);
        if (!m.placement.is_identity()) j["transform"] = {{"matrix", matrix_json(m.placement)}};
      }
      j["density"] = m.density;
      j["material"] = s.materials[std::size_t(m.material)].name;
      media.push_back(j);
    }
    root["media"] = media;
  }
  std::string out;
  write_json(root, 0, out);
  return out + "\n";
}

bool names_scene_file(const std::string& value) {
  return value.find('/') != std::string::npos ||
         (value.size() > 5 && value.compare(value.size() - 5, 5, ".json") == 0) ||
         !mesh_kind(value).empty();
}

scene load_scene(const std::string& value) {
  if (!names_scene_file(value)) return builtin_scene(value);
  if (!mesh_kind(value).empty()) return mesh_scene(value);
  return load_scene_file(value);
}

}  // namespace rtvk
