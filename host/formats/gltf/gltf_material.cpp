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

tinygltf::Value extension(const tinygltf::Material& m, const char* name) {
  const auto it = m.extensions.find(name);
  return it == m.extensions.end() ? tinygltf::Value() : it->second;
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
    const std::string k = std::to_string(materials_.size());
    materials_.push_back(b.add_material(b.name() + ":" + (mat.name.empty() ? k : mat.name),
                                        make(mat, "materials " + k)));
    const bool base = mat.pbrMetallicRoughness.baseColorTexture.index >= 0;
    const bool emissive = mat.emissiveTexture.index >= 0;
    mappings_.push_back(mapping_of(base || !emissive ? mat.pbrMetallicRoughness.baseColorTexture
                                                     : mat.emissiveTexture));
    // The emissive texture's own set, where its factor does not zero it and it reads other
    // coordinates than the first set's.
    const uv_mapping second = mapping_of(mat.emissiveTexture);
    const bool drawn = std::any_of(mat.emissiveFactor.begin(), mat.emissiveFactor.end(),
                                   [](double f) { return unit(f) > 0; });
    const bool differs =
        second.set != mappings_.back().set || second.matrix != mappings_.back().matrix;
    second_mappings_.push_back(base && emissive && drawn && differs ? std::optional(second)
                                                                    : std::nullopt);
  }
}

// A glTF material as rtvk's (docs/mesh-formats.md), until issue 45's PBR: the base color (its
// texture decoded as sRGB and tinted by the factor) and its alpha as opacity, alphaMode and
// alphaCutoff, doubleSided false as back-face culling, and the emissive factor times
// KHR_materials_emissive_strength (times the emissive texture, sRGB) as emission beside what the
// surface reflects. Its kind: KHR_materials_transmission's factor >= 0.5 is glass of
// KHR_materials_ior's index (1.5 by default); else a metallic value >= 0.5 is metal blurred by the
// roughness; else diffuse. With a metallicRoughnessTexture, the metallic and roughness values are
// the factors times the texture's mean (blue and green): a texture that marks a few metal parts
// no longer makes the whole material metal because metallicFactor defaults to 1.
material gltf_materials::make(const tinygltf::Material& mat, const std::string& where) {
  material out;
  const tinygltf::PbrMetallicRoughness& pbr = mat.pbrMetallicRoughness;
  const std::vector<double>& f = pbr.baseColorFactor;
  for (std::size_t k = 0; k < 3 && k < f.size(); ++k) out.albedo[int(k)] = unit(f[k]);
  out.opacity = f.size() == 4 ? unit(f[3]) : 1;
  if (pbr.baseColorTexture.index >= 0)
    out.texture = image_texture(pbr.baseColorTexture.index, texel_encoding::srgb, out.albedo,
                                where + " baseColorTexture");
  if (mat.alphaMode == "MASK") out.alpha = alpha_mode::mask;
  if (mat.alphaMode == "BLEND") out.alpha = alpha_mode::blend;
  out.alpha_cutoff = std::isfinite(mat.alphaCutoff) ? std::max(mat.alphaCutoff, 0.0) : 0.5;
  out.cull_back = !mat.doubleSided;
  const double strength =
      number_or(extension(mat, "KHR_materials_emissive_strength"), "emissiveStrength", 1);
  for (std::size_t k = 0; k < 3 && k < mat.emissiveFactor.size(); ++k)
    out.emission[int(k)] =
        unit(mat.emissiveFactor[k]) *
        (strength >= 0 && std::isfinite(strength) && strength < 1e6 ? strength : 1.0);
  if (mat.emissiveTexture.index >= 0 && out.emission != color(0))
    out.emission_texture = image_texture(mat.emissiveTexture.index, texel_encoding::srgb, color(1),
                                         where + " emissiveTexture");
  if (number_or(extension(mat, "KHR_materials_transmission"), "transmissionFactor", 0) >= 0.5) {
    out.type = material_type::dielectric;
    const double ior = number_or(extension(mat, "KHR_materials_ior"), "ior", 1.5);
    out.ir = ior > 0 && std::isfinite(ior) ? ior : 1.5;
    return out;
  }
  double metallic = unit(pbr.metallicFactor), roughness = unit(pbr.roughnessFactor);
  if (pbr.metallicRoughnessTexture.index >= 0) {
    const glm::dvec2 mean =
        channel_means(pbr.metallicRoughnessTexture.index, where + " metallicRoughnessTexture");
    metallic *= mean.x;
    roughness *= mean.y;
  }
  out.type = metallic >= 0.5 ? material_type::metal : material_type::lambertian;
  if (out.type == material_type::metal) out.fuzz = roughness;
  return out;
}

// The mean metallic (blue) and roughness (green) of a metallicRoughnessTexture's image, decoded
// as data (linear).
glm::dvec2 gltf_materials::channel_means(int t, const std::string& where) {
  const texel_image& image = *decoded(source_of(t, where), texel_encoding::linear, where);
  glm::dvec2 sum(0);
  for (std::uint32_t texel : image.texels)
    sum += glm::dvec2((texel >> 16) & 0xff, (texel >> 8) & 0xff);
  return image.texels.empty() ? glm::dvec2(1) : sum / (255.0 * double(image.texels.size()));
}

int gltf_materials::scene_material(int k, const std::string& where) const {
  if (k < 0 || std::size_t(k) >= materials_.size())
    b_.fail(where, "material " + std::to_string(k) + " does not exist");
  return materials_[std::size_t(k)];
}

// A texture of its own for each use of a glTF texture: the use's tint and the texture's sampler
// are the texture's, while the decoded image is shared by every use of it in one color space.
int gltf_materials::image_texture(int t, texel_encoding encoding, const color& tint,
                                  const std::string& where) {
  const int source = source_of(t, where);
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
  tex.image = decoded(source, encoding, where);
  return b_.add_texture(std::move(tex));
}

// The image texture t shows; fails naming `where` if there is none.
int gltf_materials::source_of(int t, const std::string& where) const {
  if (t < 0 || std::size_t(t) >= m_.textures.size())
    b_.fail(where, "texture " + std::to_string(t) + " does not exist");
  const int source = m_.textures[std::size_t(t)].source;
  if (source < 0 || std::size_t(source) >= m_.images.size())
    b_.fail(where, "texture " + std::to_string(t) + " has no image");
  return source;
}

// Image `source` decoded in one color space, once however many textures use it.
std::shared_ptr<const texel_image> gltf_materials::decoded(int source, texel_encoding encoding,
                                                           const std::string& where) {
  std::shared_ptr<const texel_image>& image = images_[{source, encoding}];
  if (!image) {
    const tinygltf::Image& img = m_.images[std::size_t(source)];
    if (img.image.empty() && img.uri.rfind("data:", 0) == 0)
      b_.fail(where, "image " + std::to_string(source) + ": its data URI (" +
                         std::to_string(img.uri.size()) + " characters) is not valid base64");
    if (img.image.empty() && !img.uri.empty())
      b_.fail(where, "image " + std::to_string(source) + ": " + img.uri + " not found");
    if (img.image.empty()) b_.fail(where, "image " + std::to_string(source) + " has no data");
    image = decode_texel_image(std::string(img.image.begin(), img.image.end()),
                               b_.name() + ": images/" + std::to_string(source), encoding);
  }
  return image;
}

}  // namespace rtvk
