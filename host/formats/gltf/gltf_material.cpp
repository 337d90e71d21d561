// glTF materials as rtvk's (docs/mesh-formats.md), and the image textures they use.
#include <algorithm>
#include <cmath>

#include "gltf_reader.h"

namespace rtvk {
namespace {

double number_or(const tinygltf::Value& v, const char* key, double fallback) {
  if (!v.IsObject() || !v.Has(key) || !v.Get(key).IsNumber()) return fallback;
  return v.Get(key).GetNumberAsDouble();
}

double unit(double x) {
  return std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0);
}

// A glTF material as one of rtvk's (docs/geometry.md): an emissive factor that is not black is a
// lamp of that color (times KHR_materials_emissive_strength); else KHR_materials_transmission's
// factor >= 0.5 is glass of KHR_materials_ior's index (1.5 by default); else metallicFactor >=
// 0.5 is metal of the base color, blurred by the roughness; else diffuse of the base color. A
// base color texture (`base_texture`, the scene's texture index, or -1; the factor tints it)
// stands in for the base color.
material from_gltf(const tinygltf::Material& m, int base_texture) {
  material out;
  const auto ext = [&](const char* name) {
    const auto it = m.extensions.find(name);
    return it == m.extensions.end() ? tinygltf::Value() : it->second;
  };
  color emit(0);
  for (std::size_t k = 0; k < 3 && k < m.emissiveFactor.size(); ++k)
    emit[int(k)] = unit(m.emissiveFactor[k]);
  // An emissive texture marks the parts of a surface that glow (a lamp's dial, a screen); rtvk's
  // lamps emit everywhere and reflect nothing, so such a material stays what its base color makes
  // it rather than turning wholly into a lamp.
  if (emit != color(0) && m.emissiveTexture.index < 0) {
    const double strength =
        number_or(ext("KHR_materials_emissive_strength"), "emissiveStrength", 1);
    out.type = material_type::diffuse_light;
    out.albedo =
        emit * (strength >= 0 && std::isfinite(strength) && strength < 1e6 ? strength : 1.0);
    return out;
  }
  if (number_or(ext("KHR_materials_transmission"), "transmissionFactor", 0) >= 0.5) {
    out.type = material_type::dielectric;
    const double ior = number_or(ext("KHR_materials_ior"), "ior", 1.5);
    out.ir = ior > 0 && std::isfinite(ior) ? ior : 1.5;
    return out;
  }
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
  color base(1);
  for (std::size_t k = 0; k < 3 && k < pbr.baseColorFactor.size(); ++k)
    base[int(k)] = unit(pbr.baseColorFactor[k]);
  out.albedo = base;
  out.texture = base_texture;
  if (pbr.metallicFactor >= 0.5) {
    out.type = material_type::metal;
    out.fuzz = unit(pbr.roughnessFactor);
    return out;
  }
  out.type = material_type::lambertian;
  return out;
}

// A glTF sampler's wrap mode as an image texture's.
image_wrap wrap_of(int gl_wrap) {
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return image_wrap::clamp;
  if (gl_wrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return image_wrap::mirror;
  return image_wrap::repeat;
}

// A textureInfo's texture coordinates: its texCoord, or KHR_texture_transform's texCoord where
// that is given, mapped by the transform's offset * rotation * scale. The rotation turns as
// Cesium and three.js turn it (the ones TextureTransformTest's markers were made against):
// u' = cos r u + sin r v, v' = cos r v - sin r u.
uv_mapping mapping_of(const tinygltf::TextureInfo& info) {
  uv_mapping out;
  out.set = info.texCoord;
  const auto it = info.extensions.find("KHR_texture_transform");
  if (it == info.extensions.end() || !it->second.IsObject()) return out;
  const tinygltf::Value& t = it->second;
  const auto pair = [&](const char* key, glm::dvec2 fallback) {
    if (!t.Has(key) || !t.Get(key).IsArray() || t.Get(key).ArrayLen() != 2) return fallback;
    for (int k = 0; k < 2; ++k)
      if (t.Get(key).Get(k).IsNumber()) fallback[k] = t.Get(key).Get(k).GetNumberAsDouble();
    return fallback;
  };
  const glm::dvec2 offset = pair("offset", glm::dvec2(0)), scale = pair("scale", glm::dvec2(1));
  const double r = number_or(t, "rotation", 0);
  if (t.Has("texCoord") && t.Get("texCoord").IsInt()) out.set = t.Get("texCoord").GetNumberAsInt();
  const glm::dmat3 translation(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);  // column-major
  const glm::dmat3 rotation(std::cos(r), -std::sin(r), 0, std::sin(r), std::cos(r), 0, 0, 0, 1);
  const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
  out.matrix = translation * rotation * scaling;
  return out;
}

}  // namespace

gltf_materials::gltf_materials(const tinygltf::Model& m, mesh_builder& b) : m_(m), b_(b) {
  for (const tinygltf::Material& mat : m.materials) {
    materials_.push_back(b.add_material(
        b.name() + ":" + (mat.name.empty() ? std::to_string(materials_.size()) : mat.name),
        from_gltf(mat, base_texture(mat))));
    const bool base = mat.pbrMetallicRoughness.baseColorTexture.index >= 0;
    mappings_.push_back(mapping_of(base || mat.emissiveTexture.index < 0
                                       ? mat.pbrMetallicRoughness.baseColorTexture
                                       : mat.emissiveTexture));
  }
}

int gltf_materials::scene_material(int k, const std::string& where) const {
  if (k < 0 || std::size_t(k) >= materials_.size())
    b_.fail(where, "material " + std::to_string(k) + " does not exist");
  return materials_[std::size_t(k)];
}

// The scene's texture for a material's base color (tinted by its factor), or -1.
int gltf_materials::base_texture(const tinygltf::Material& mat) {
  const tinygltf::TextureInfo& info = mat.pbrMetallicRoughness.baseColorTexture;
  if (info.index < 0) return -1;
  const std::string where = "materials \"" + mat.name + "\" baseColorTexture";
  if (info.texCoord != 0)
    b_.fail(where,
            "reads TEXCOORD_" + std::to_string(info.texCoord) + " (rtvk reads TEXCOORD_0 only)");
  color tint(1);
  const std::vector<double>& f = mat.pbrMetallicRoughness.baseColorFactor;
  for (std::size_t k = 0; k < 3 && k < f.size(); ++k) tint[int(k)] = unit(f[k]);
  return image_texture(info.index, texel_encoding::book, tint, where);
}

// A texture of its own for each use of a glTF texture: the use's tint and the texture's sampler
// are the texture's, while the decoded image is shared by every use of it in one color space.
int gltf_materials::image_texture(int t, texel_encoding encoding, const color& tint,
                                  const std::string& where) {
  if (t < 0 || std::size_t(t) >= m_.textures.size())
    b_.fail(where, "texture " + std::to_string(t) + " does not exist");
  const int source = m_.textures[std::size_t(t)].source;
  if (source < 0 || std::size_t(source) >= m_.images.size())
    b_.fail(where, "texture " + std::to_string(t) + " has no image");
  texture tex;
  tex.type = texture_type::image;
  // Absolute, so that a dumped scene finds the file from wherever it is read.
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::absolute(b_.name(), ec);
  tex.file =
      (ec ? b_.name() : file.lexically_normal().string()) + "#images/" + std::to_string(source);
  tex.even = tint;
  const int sampler = m_.textures[std::size_t(t)].sampler;
  if (sampler >= 0 && std::size_t(sampler) < m_.samplers.size()) {
    tex.wrap_u = wrap_of(m_.samplers[std::size_t(sampler)].wrapS);
    tex.wrap_v = wrap_of(m_.samplers[std::size_t(sampler)].wrapT);
  } else {
    tex.wrap_u = tex.wrap_v = image_wrap::repeat;  // glTF's default sampler
  }
  std::shared_ptr<const texel_image>& image = images_[{source, encoding}];
  if (!image) {
    const tinygltf::Image& img = m_.images[std::size_t(source)];
    if (img.image.empty()) b_.fail(where, "image " + std::to_string(source) + " has no data");
    image = decode_texel_image(std::string(img.image.begin(), img.image.end()),
                               b_.name() + ": images/" + std::to_string(source), encoding);
  }
  tex.image = image;
  return b_.add_texture(std::move(tex));
}

}  // namespace rtvk
