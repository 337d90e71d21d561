// glTF's metallic-roughness parameters and the KHR_materials_* extensions rtvk reads, as
// pbr_material's (docs/mesh-formats.md's table): each factor exactly as the file gives it, checked
// against the range its specification gives (out of it: exit 2 naming the field and the value),
// each texture decoded in the color space glTF gives it (colors sRGB, data linear) and read from
// the channel glTF names (pbr_material.h). occlusionTexture is not read: a path tracer computes
// the occlusion it approximates.
#include <cmath>
#include <limits>

#include "gltf_reader.h"

namespace rtvk {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// Checks each field of one object of a material (pbrMetallicRoughness, an extension) against its
// specification's range, naming "materials K OBJECT FIELD" where it is out.
class field_reader {
 public:
  field_reader(const mesh_builder& b, std::string where) : b_(b), where_(std::move(where)) {}

  // A number within [lo, hi] (above lo where `open`); `fallback` where absent.
  double number(const tinygltf::Value& v, const char* key, double fallback, double lo, double hi,
                bool open = false) const {
    if (!v.Has(key)) return fallback;
    if (!v.Get(key).IsNumber()) fail(key, "expected a number");
    return checked(v.Get(key).GetNumberAsDouble(), key, lo, hi, open);
  }

  // x, checked finite and within [lo, hi] (above lo where `open`).
  double checked(double x, const std::string& key, double lo, double hi, bool open = false) const {
    if (!std::isfinite(x) || x < lo || (open && x == lo) || x > hi)
      fail(key, "must be " + range(lo, hi, open) + ", got " + format_number(x));
    return x;
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    b_.fail(where_ + " " + key, what);
  }

  // Three numbers, each within [lo, hi].
  color rgb(const tinygltf::Value& v, const char* key, color fallback, double lo, double hi) const {
    if (!v.Has(key)) return fallback;
    const tinygltf::Value& a = v.Get(key);
    if (!a.IsArray() || a.ArrayLen() != 3) fail(key, "expected an array of 3 numbers");
    for (int c = 0; c < 3; ++c) {
      if (!a.Get(c).IsNumber()) fail(key, "expected an array of 3 numbers");
      fallback[c] = checked(a.Get(c).GetNumberAsDouble(),
                            std::string(key) + "[" + std::to_string(c) + "]", lo, hi);
    }
    return fallback;
  }

  // A textureInfo inside an extension (tinygltf parses only the core ones); index -1 where absent.
  tinygltf::TextureInfo texture(const tinygltf::Value& v, const char* key) const {
    tinygltf::TextureInfo info;
    if (!v.Has(key)) return info;
    const tinygltf::Value& t = v.Get(key);
    if (!t.IsObject() || !t.Has("index") || !t.Get("index").IsInt() ||
        t.Get("index").GetNumberAsInt() < 0)
      fail(key, "expected a textureInfo with an index");
    info.index = t.Get("index").GetNumberAsInt();
    if (t.Has("texCoord")) {
      if (!t.Get("texCoord").IsInt() || t.Get("texCoord").GetNumberAsInt() < 0)
        fail(std::string(key) + " texCoord", "expected an integer >= 0");
      info.texCoord = t.Get("texCoord").GetNumberAsInt();
    }
    if (t.Has("extensions") && t.Get("extensions").IsObject())
      for (const std::string& e : t.Get("extensions").Keys())
        info.extensions[e] = t.Get("extensions").Get(e);
    return info;
  }

  const std::string& where() const { return where_; }

 private:
  static std::string range(double lo, double hi, bool open) {
    if (lo == -infinity) return "finite";
    if (hi == infinity) return (open ? "> " : ">= ") + format_number(lo);
    return "in [" + format_number(lo) + ", " + format_number(hi) + "]";
  }

  const mesh_builder& b_;
  std::string where_;  // "materials K OBJECT"
};

// The material's extension object `name`; null where it has none.
const tinygltf::Value* extension_of(const tinygltf::Material& m, const char* name) {
  const auto it = m.extensions.find(name);
  return it == m.extensions.end() || !it->second.IsObject() ? nullptr : &it->second;
}

tinygltf::TextureInfo info_of(const tinygltf::NormalTextureInfo& n) {
  tinygltf::TextureInfo info;
  info.index = n.index;
  info.texCoord = n.texCoord;
  info.extensions = n.extensions;
  return info;
}

}  // namespace

// pbrMetallicRoughness's metallic and roughness (factors in [0, 1]; the texture's blue and green,
// linear), normalTexture (linear; its scale any finite number), then the extensions.
void gltf_materials::read_pbr(const tinygltf::Material& mat, std::size_t k, pbr_material& p,
                              const std::string& where) {
  const tinygltf::PbrMetallicRoughness& mr = mat.pbrMetallicRoughness;
  const field_reader core(b_, where + " pbrMetallicRoughness");
  p.metallic = core.checked(mr.metallicFactor, "metallicFactor", 0, 1);
  p.roughness = core.checked(mr.roughnessFactor, "roughnessFactor", 0, 1);
  p.metallic_roughness_texture =
      parameter_texture(mr.metallicRoughnessTexture, texel_encoding::linear, k,
                        core.where() + " metallicRoughnessTexture");
  if (mat.normalTexture.index >= 0) {
    p.normal_scale = field_reader(b_, where + " normalTexture")
                         .checked(mat.normalTexture.scale, "scale", -infinity, infinity);
    p.normal_texture = parameter_texture(info_of(mat.normalTexture), texel_encoding::linear, k,
                                         where + " normalTexture");
  }
  read_extensions(mat, k, p, where);
}

// KHR_materials_ior, _specular, _transmission, _volume, _clearcoat and _sheen, each field with its
// specification's default and range.
void gltf_materials::read_extensions(const tinygltf::Material& mat, std::size_t k, pbr_material& p,
                                     const std::string& where) {
  const texel_encoding linear = texel_encoding::linear, srgb = texel_encoding::srgb;
  const auto tex = [&](const field_reader& r, const tinygltf::Value& v, const char* key,
                       texel_encoding e) {
    return parameter_texture(r.texture(v, key), e, k, r.where() + " " + key);
  };
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_ior")) {
    const field_reader r(b_, where + " KHR_materials_ior");
    // At least 1, or exactly 0: the Fresnel term 1 (specular-glossiness files).
    p.ior = r.number(*v, "ior", 1.5, -infinity, infinity);
    if (p.ior != 0 && p.ior < 1) r.fail("ior", "must be >= 1 or 0, got " + format_number(p.ior));
  }
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_specular")) {
    const field_reader r(b_, where + " KHR_materials_specular");
    p.specular = r.number(*v, "specularFactor", 1, 0, 1);
    p.specular_texture = tex(r, *v, "specularTexture", linear);
    p.specular_color = r.rgb(*v, "specularColorFactor", color(1), 0, infinity);
    p.specular_color_texture = tex(r, *v, "specularColorTexture", srgb);
  }
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_transmission")) {
    const field_reader r(b_, where + " KHR_materials_transmission");
    p.transmission = r.number(*v, "transmissionFactor", 0, 0, 1);
    p.transmission_texture = tex(r, *v, "transmissionTexture", linear);
  }
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_volume")) {
    const field_reader r(b_, where + " KHR_materials_volume");
    p.thickness = r.number(*v, "thicknessFactor", 0, 0, infinity);
    p.thickness_texture = tex(r, *v, "thicknessTexture", linear);
    p.attenuation_color = r.rgb(*v, "attenuationColor", color(1), 0, 1);
    p.attenuation_distance = r.number(*v, "attenuationDistance", infinity, 0, infinity, true);
  }
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_clearcoat")) {
    const field_reader r(b_, where + " KHR_materials_clearcoat");
    p.clearcoat = r.number(*v, "clearcoatFactor", 0, 0, 1);
    p.clearcoat_texture = tex(r, *v, "clearcoatTexture", linear);
    p.clearcoat_roughness = r.number(*v, "clearcoatRoughnessFactor", 0, 0, 1);
    p.clearcoat_roughness_texture = tex(r, *v, "clearcoatRoughnessTexture", linear);
    p.clearcoat_normal_texture = tex(r, *v, "clearcoatNormalTexture", linear);
    if (p.clearcoat_normal_texture >= 0 && v->Get("clearcoatNormalTexture").Has("scale"))
      p.clearcoat_normal_scale =
          field_reader(b_, r.where() + " clearcoatNormalTexture")
              .number(v->Get("clearcoatNormalTexture"), "scale", 1, -infinity, infinity);
  }
  if (const tinygltf::Value* v = extension_of(mat, "KHR_materials_sheen")) {
    const field_reader r(b_, where + " KHR_materials_sheen");
    p.sheen_color = r.rgb(*v, "sheenColorFactor", color(0), 0, 1);
    p.sheen_color_texture = tex(r, *v, "sheenColorTexture", srgb);
    p.sheen_roughness = r.number(*v, "sheenRoughnessFactor", 0, 0, 1);
    p.sheen_roughness_texture = tex(r, *v, "sheenRoughnessTexture", linear);
  }
}

}  // namespace rtvk
