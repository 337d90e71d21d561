// The scene file's materials and their textures: each material kind's fields (material.cpp's
// table says which a kind reads), a color or a texture in its color field, and the images those
// textures decode, each once per file; read and written side by side.
#include "errors.h"
#include "format.h"
#include "mesh_file.h"
#include "scene_file_fields.h"

namespace rtvk::scene_json {
namespace {

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

// An image file's color space, as "color_space" names it: the book's gamma 2.2 (the default, what
// every scene file had), sRGB, or linear data.
const char* space_name(const texture& t) {
  switch (t.color_space) {
    case texel_encoding::srgb:
      return "srgb";
    case texel_encoding::linear:
      return "linear";
    case texel_encoding::book:
      break;
  }
  return "book";
}

texel_encoding read_color_space(const scene_reader& r, const json& j, const std::string& p) {
  const std::string name = j.is_string() ? j.get<std::string>() : "";
  if (name == "book") return texel_encoding::book;
  if (name == "srgb") return texel_encoding::srgb;
  if (name == "linear") return texel_encoding::linear;
  r.fail(p, "expected \"book\", \"srgb\" or \"linear\", got " + j.dump());
}

// An image texture's "file" (at `p`): decoded once per file however many textures name it, rtvk's
// own planet, or a glTF's embedded image (FILE#images/N, as rtvk scene dump names a mesh's base
// color texture); every file in the folder the scene's files may use.
void read_image(const scene_reader& r, const json& f, const std::string& p, texture& tex) {
  if (!f.is_string() || f.get<std::string>().empty())
    r.fail(p, "expected a file name, got " + r.type_of(f));
  tex.file = f.get<std::string>();
  const std::string field = r.file() + ": " + p;
  const std::size_t hash = tex.file.rfind("#images/");
  // Decoded once per file and color space (the book's keeps the file's name as its key).
  const std::string key =
      tex.color_space == texel_encoding::book ? tex.file : tex.file + "#" + space_name(tex);
  std::shared_ptr<const texel_image>& cached = r.images[key];
  if (cached) {
    tex.image = cached;
  } else if (tex.file == builtin_planet) {
    tex.image = planet_image(1024, 512, 0);
  } else if (hash != std::string::npos && !mesh_kind(tex.file.substr(0, hash)).empty()) {
    const std::string n = tex.file.substr(hash + 8);
    if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos)
      r.fail(p, "expected FILE#images/N, got \"" + tex.file + "\"");
    const std::filesystem::path file = r.base() / tex.file.substr(0, hash);
    r.guard().check(file, field, tex.file);
    tex.image = gltf_image(
        file, std::stoul(n), field, r.guard(),
        tex.color_space == texel_encoding::linear ? texel_encoding::linear : texel_encoding::srgb);
  } else {
    const std::filesystem::path file = r.base() / tex.file;
    r.guard().check(file, field, tex.file);
    tex.image = load_texel_image(file, field, tex.color_space);
  }
  cached = tex.image;
  std::uint64_t texels = 0;
  for (const auto& [name, image] : r.images)
    if (image) texels += image->texels.size();
  if (texels > max_scene_texels)
    r.fail(p, "the scene's images hold " + std::to_string(texels) + " texels, past the limit of " +
                  std::to_string(max_scene_texels));
}

}  // namespace

// A color field that may be a texture instead: a color (in [0, 1], or any value >= 0 for a lamp's
// `emit`), or a texture object ({"type": "checker" | "image" | "noise" | "solid", ...}), which is
// appended to s.textures. Sets m.albedo or m.texture.
void read_color_or_texture(const scene_reader& r, const json& j, const std::string& p,
                           bool radiance, scene& s, material& m) {
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
    r.only_fields(j, p, {"type", "file", "color", "wrap", "color_space"});
    tex.type = texture_type::image;
    if (j.contains("color_space"))
      tex.color_space = read_color_space(r, j["color_space"], p + "/color_space");
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
    read_image(r, r.required(j, p, "file"), p + "/file", tex);
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

namespace {

// An alpha mode's name, as glTF spells it in lower case.
const char* alpha_name(alpha_mode a) {
  return a == alpha_mode::mask ? "mask" : a == alpha_mode::blend ? "blend" : "opaque";
}

// The fields every kind of material takes beyond the books' (material.h; glTF's and MTL's):
// emission and its texture, alpha mode, opacity and cutoff, back-face culling.
const std::initializer_list<const char*> surface_fields = {
    "emission", "emission_texture", "alpha_mode", "opacity", "alpha_cutoff", "cull_back"};

void read_surface(const scene_reader& r, const json& j, const std::string& p, scene& s,
                  material& m) {
  if (j.contains("emission")) m.emission = r.radiance(j["emission"], p + "/emission");
  if (j.contains("emission_texture")) {
    const json& t = j["emission_texture"];
    if (!t.is_object() || (t.contains("type") && t["type"] == "solid"))
      r.fail(p + "/emission_texture", "expected a texture object, got " + r.type_of(t));
    material e;
    read_color_or_texture(r, t, p + "/emission_texture", true, s, e);
    m.emission_texture = e.texture;
    if (!j.contains("emission")) m.emission = color(1);  // the texture alone is the radiance
  }
  if (j.contains("alpha_mode")) {
    const json& a = j["alpha_mode"];
    bool known = false;
    for (alpha_mode mode : {alpha_mode::opaque, alpha_mode::mask, alpha_mode::blend})
      if (a.is_string() && a.get<std::string>() == alpha_name(mode)) {
        m.alpha = mode;
        known = true;
      }
    if (!known)
      r.fail(p + "/alpha_mode",
             "expected \"opaque\", \"mask\" or \"blend\", got " +
                 (a.is_string() ? "\"" + a.get<std::string>() + "\"" : r.type_of(a)));
  }
  if (j.contains("opacity")) m.opacity = r.number_in(j["opacity"], p + "/opacity", 0, 1);
  if (j.contains("alpha_cutoff"))
    m.alpha_cutoff = r.number_in(j["alpha_cutoff"], p + "/alpha_cutoff", 0, 1);
  m.cull_back = r.flag(j, p, "cull_back");
}

void write_surface(const scene& s, const material& m, json& j) {
  if (m.emission != color(0)) j["emission"] = vec_json(m.emission);
  if (m.emission_texture >= 0)
    j["emission_texture"] = texture_json(s.textures[std::size_t(m.emission_texture)]);
  if (m.alpha != alpha_mode::opaque) j["alpha_mode"] = alpha_name(m.alpha);
  if (m.opacity != 1) j["opacity"] = m.opacity;
  if (m.alpha_cutoff != 0.5) j["alpha_cutoff"] = m.alpha_cutoff;
  if (m.cull_back) j["cull_back"] = true;
}

material read_material(const scene_reader& r, const json& j, const std::string& p, scene& s) {
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
  const bool pbr = kind->type == material_type::pbr;
  if (pbr)
    for (const std::string& f : pbr_fields()) fields.insert(f);
  fields.insert(surface_fields.begin(), surface_fields.end());
  r.only_fields(j, p, fields);
  material m;
  m.type = kind->type;
  if (kind->albedo)
    read_color_or_texture(r, r.required(j, p, color_field), p + "/" + color_field, lamp, s, m);
  if (kind->fuzz && j.contains("fuzz")) m.fuzz = r.number_in(j["fuzz"], p + "/fuzz", 0, 1);
  m.one_sided = lamp && r.flag(j, p, "one_sided");
  if (kind->ir) {
    m.ir = r.number(r.required(j, p, "ir"), p + "/ir");
    if (m.ir <= 0)
      r.fail(p + "/ir", "expected an index of refraction > 0, got " + format_number(m.ir));
  }
  if (pbr) read_pbr(r, j, p, s, m);
  read_surface(r, j, p, s, m);
  return m;
}

}  // namespace

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
      if (t.color_space != texel_encoding::book) j["color_space"] = space_name(t);
      if (t.even != color(1)) j["color"] = vec_json(t.even);
      if (t.wrap_u != t.wrap_v)
        j["wrap"] = json::array({wrap_name(t.wrap_u), wrap_name(t.wrap_v)});
      else if (t.wrap_u != image_wrap::clamp)
        j["wrap"] = wrap_name(t.wrap_u);
      break;
  }
  return j;
}

// Fills s.materials from /materials, in the file's order, and each name's index there.
void read_materials(const scene_reader& r, const json& root, scene& s) {
  if (root.contains("noise_seed"))
    s.noise_seed = std::uint32_t(r.integer(root["noise_seed"], "/noise_seed", 0, 0xffffffffll));
  if (!root.contains("materials")) return;
  const json& mats = root["materials"];
  if (!mats.is_object())
    r.fail("/materials", "expected an object of named materials, got " + r.type_of(mats));
  for (const auto& [key, value] : mats.items()) {
    r.material_index[key] = int(s.materials.size());
    material m = read_material(r, value, "/materials/" + escape_pointer(key), s);
    s.materials.push_back({key, m});
  }
}

void write_materials(const scene& s, json& root) {
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
    if (m.type == material_type::pbr) write_pbr(s, m, j);
    write_surface(s, m, j);
    mats[name] = j;
  }
  root["materials"] = mats;
}

}  // namespace rtvk::scene_json
