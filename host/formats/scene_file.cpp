// The scene file (docs/scene-format.md): the top level, which hands each part of the document to
// its reader and writer (the table `sections`), the render settings and the sky, and the file
// itself: reading, parsing, pretty-printing.
#include "scene_file.h"

#include <nlohmann/json.hpp>

#include "builtin_showcase.h"
#include "errors.h"
#include "format.h"
#include "input_file.h"
#include "light_sources.h"
#include "mesh_file.h"
#include "parse_values.h"
#include "scene_file_fields.h"

namespace rtvk {
namespace scene_json {
namespace {

// How the file's 8-bit images are encoded (docs/color.md): "view_transform" when given; else a
// file that sets "gamma" keeps the power law it always had, and any other file, new ones, gets
// standard (sRGB). A file without a "render" object gets standard too (read_settings).
void read_view(const scene_reader& r, const json& j, render_settings& s) {
  const std::string p = "/render";
  if (j.contains("gamma")) s.gamma = r.number_in(j["gamma"], p + "/gamma", 0.1, 10);
  s.transform = j.contains("gamma") ? view_transform::gamma : view_transform::standard;
  if (j.contains("view_transform")) {
    const json& v = j["view_transform"];
    const auto t = view_transform_from_name(v.is_string() ? v.get<std::string>() : "");
    if (!t)
      r.fail(p + "/view_transform",
             std::string("expected ") + view_transform_words + ", got " + v.dump());
    s.transform = *t;
  }
  if (j.contains("exposure"))
    s.exposure = r.number_in(j["exposure"], p + "/exposure", -max_exposure, max_exposure);
}

render_settings read_render(const scene_reader& r, const json& j) {
  const std::string p = "/render";
  r.only_fields(j, p,
                {"width", "aspect", "spp", "max_depth", "seed", "gamma", "view_transform",
                 "exposure", "jitter", "sampling"});
  render_settings s;
  read_view(r, j, s);
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
    else if (name == "nee")
      s.sampling = sampling_mode::nee;
    else
      r.fail(p + "/sampling",
             "expected \"plain\", \"lights\", \"nee\" or \"auto\", got " + m.dump());
  }
  return s;
}

void read_settings(const scene_reader& r, const json& root, scene& s) {
  s.render = read_render(r, root.contains("render") ? root["render"] : json::object());
}

void write_settings(const scene& s, json& root) {
  const render_settings& r = s.render;
  root["render"] = {{"width", r.width},
                    {"aspect", r.aspect},
                    {"spp", r.spp},
                    {"max_depth", r.max_depth},
                    {"seed", r.seed},
                    {"gamma", r.gamma},
                    {"view_transform", view_transform_name(r.transform)},
                    {"jitter", r.jitter}};
  if (r.exposure != 0) root["render"]["exposure"] = r.exposure;
  if (r.sampling != sampling_mode::automatic)
    root["render"]["sampling"] = sampling_name(r.sampling);
}

// A sky's two colors, or the second book's constant "background" color: a uniform sky.
void read_sky(const scene_reader& r, const json& root, scene& s) {
  if (root.contains("sky")) {
    const json& j = root["sky"];
    r.only_fields(j, "/sky", {"horizon", "zenith"});
    if (j.contains("horizon")) s.sky.horizon = r.radiance(j["horizon"], "/sky/horizon");
    if (j.contains("zenith")) s.sky.zenith = r.radiance(j["zenith"], "/sky/zenith");
  }
  if (root.contains("background")) {
    if (root.contains("sky")) r.fail("/background", "a scene has a sky or a background, not both");
    s.sky.horizon = s.sky.zenith = r.radiance(root["background"], "/background");
  }
}

void write_sky(const scene& s, json& root) {
  if (s.sky.horizon == s.sky.zenith)
    root["background"] = vec_json(s.sky.horizon);
  else
    root["sky"] = {{"horizon", vec_json(s.sky.horizon)}, {"zenith", vec_json(s.sky.zenith)}};
}

// The environment map escaping rays see instead of the sky (docs/lighting.md): its file, relative
// to the scene file and within the folder its files may use, and how it is turned and scaled.
void read_environment(const scene_reader& r, const json& root, scene& s) {
  if (!root.contains("environment")) return;
  const std::string p = "/environment";
  const json& j = root["environment"];
  r.only_fields(j, p, {"file", "rotation", "strength", "visible"});
  const json& f = r.required(j, p, "file");
  if (!f.is_string() || f.get<std::string>().empty())
    r.fail(p + "/file", "expected a file name, got " + r.type_of(f));
  environment_map e;
  e.file = f.get<std::string>();
  const std::string field = r.file() + ": " + p + "/file";
  // builtin:sky-sun is rtvk's own map, drawn rather than read: no file to look for or confine.
  const bool own = e.file == builtin_sky_sun;
  const std::filesystem::path file = own ? std::filesystem::path(e.file) : r.base() / e.file;
  if (!own) r.guard().check(file, field, e.file);
  e.image = load_environment_image(file, field);
  if (j.contains("rotation")) e.rotation = r.number_in(j["rotation"], p + "/rotation", -3600, 3600);
  if (j.contains("strength")) e.strength = r.number_in(j["strength"], p + "/strength", 0, 1e9);
  if (j.contains("visible")) {
    if (!j["visible"].is_boolean())
      r.fail(p + "/visible", "expected true or false, got " + r.type_of(j["visible"]));
    e.visible = j["visible"].get<bool>();
  }
  s.environment = std::move(e);
}

void write_environment(const scene& s, json& root) {
  if (!s.environment) return;
  const environment_map& e = *s.environment;
  root["environment"] = {
      {"file", e.file}, {"rotation", e.rotation}, {"strength", e.strength}, {"visible", e.visible}};
}

// Each part of a scene file: the top-level fields it owns, its reader and its writer. Parts are
// read and written in this order: cameras first, materials before the objects that name them.
struct section {
  std::vector<const char*> fields;  // the top-level keys it reads
  void (*read)(const scene_reader& r, const json& root, scene& s);
  void (*write)(const scene& s, json& root);
};

void read_scene_objects(const scene_reader& r, const json& root, scene& s) {
  read_objects(r, root, "", s);
}
void write_scene_objects(const scene& s, json& root) {
  write_objects(root, s, s);
}

const section sections[] = {
    {{"camera", "cameras"}, read_cameras, write_cameras},
    {{"render"}, read_settings, write_settings},
    {{"sky", "background"}, read_sky, write_sky},
    {{"environment"}, read_environment, write_environment},
    {{"noise_seed", "materials"}, read_materials, write_materials},
    {object_fields(), read_scene_objects, write_scene_objects},
    {{"groups", "instances"}, read_groups, write_groups},
    {{"media"}, read_media, write_media},
    {{"lights"}, read_lights, write_lights},
};

scene read_scene(const scene_reader& r, const json& root, const std::string& name) {
  std::set<std::string> fields;
  for (const section& part : sections) fields.insert(part.fields.begin(), part.fields.end());
  r.only_fields(root, "", fields);
  scene s;
  s.name = name;
  for (const section& part : sections) part.read(r, root, s);
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

// Pretty-prints with anything that fits on one line kept on one line: a sphere or a vector
// reads as one line rather than ten.
// Strings that are not UTF-8 (a texture's file name in Latin-1) are written with U+FFFD in
// place of their bad bytes rather than failing the dump (names are made UTF-8 when read).
void write_json(const json& j, int indent, std::string& out) {
  const std::string flat = j.dump(-1, ' ', false, json::error_handler_t::replace);
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
    if (object) out += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ": ";
    write_json(*it, indent + 2, out);
    out += i + 1 < j.size() ? ",\n" : "\n";
  }
  out += std::string(std::size_t(indent), ' ') + (object ? "}" : "]");
}

}  // namespace
}  // namespace scene_json

scene parse_scene_json(const std::string& text, const std::string& file_name,
                       const file_access& access) {
  using scene_json::json;
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
  std::filesystem::path base = std::filesystem::path(file_name).parent_path();
  if (base.empty()) base = ".";
  scene_json::scene_reader r(file_name, base, path_guard::of(access, base));
  return scene_json::read_scene(r, root, file_name);
}

scene load_scene_file(const std::filesystem::path& path, const file_access& access) {
  const std::string text = read_regular_file(path, max_scene_file_bytes, "scene file");
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw usage_error(path.string() + ": empty scene file");
  return parse_scene_json(text, path.string(), access);
}

std::string dump_scene_json(const scene& s) {
  scene_json::json root;
  for (const scene_json::section& part : scene_json::sections) part.write(s, root);
  std::string out;
  scene_json::write_json(root, 0, out);
  return out + "\n";
}

bool names_scene_file(const std::string& value) {
  return value.find('/') != std::string::npos ||
         (value.size() > 5 && value.compare(value.size() - 5, 5, ".json") == 0) ||
         !mesh_kind(value).empty();
}

std::vector<std::string> scene_names() {
  std::vector<std::string> names = builtin_scene_names();
  for (const std::string& n : format_scene_names()) names.push_back(n);
  return names;
}

scene load_scene(const std::string& value, const file_access& access) {
  if (value == "showcase") return showcase_scene();
  if (!names_scene_file(value)) return builtin_scene(value);
  if (!mesh_kind(value).empty()) return mesh_scene(value, access);
  return load_scene_file(value, access);
}

}  // namespace rtvk
