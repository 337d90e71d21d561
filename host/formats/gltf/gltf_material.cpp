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
    const std::size_t k = materials_.size();
    const bool base = mat.pbrMetallicRoughness.baseColorTexture.index >= 0;
    const bool emissive = mat.emissiveTexture.index >= 0;
    mappings_.push_back(mapping_of(base || !emissive ? mat.pbrMetallicRoughness.baseColorTexture
                                                     : mat.emissiveTexture));
    mapped_.push_back(base || emissive);
    // The emissive texture's own set, where its factor does not zero it and it reads other
    // coordinates than the first set's.
    const uv_mapping second = mapping_of(mat.emissiveTexture);
    const bool drawn = std::any_of(mat.emissiveFactor.begin(), mat.emissiveFactor.end(),
                                   [](double f) { return unit(f) > 0; });
    const bool differs =
        second.set != mappings_.back().set || second.matrix != mappings_.back().matrix;
    second_mappings_.push_back(base && emissive && drawn && differs ? std::optional(second)
                                                                    : std::nullopt);
    const std::string n = std::to_string(k);
    materials_.push_back(b.add_material(b.name() + ":" + (mat.name.empty() ? n : mat.name),
                                        make(mat, k, "materials " + n)));
  }
}

// A glTF material as rtvk's pbr material (docs/mesh-formats.md's table): the base color (its
// texture decoded as sRGB and tinted by the factor) and its alpha as opacity, alphaMode and
// alphaCutoff, doubleSided false as back-face culling, and the emissive factor times
// KHR_materials_emissive_strength (times the emissive texture, sRGB) as emission beside what the
// surface reflects; the metallic-roughness parameters and the extensions are read_pbr's.
// KHR_materials_unlit makes it rtvk's unlit kind (flat) of the same base color.
material gltf_materials::make(const tinygltf::Material& mat, std::size_t k,
                              const std::string& where) {
  material out;
  const tinygltf::PbrMetallicRoughness& pbr = mat.pbrMetallicRoughness;
  const std::vector<double>& f = pbr.baseColorFactor;
  for (std::size_t c = 0; c < 3 && c < f.size(); ++c) out.albedo[int(c)] = unit(f[c]);
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
  for (std::size_t c = 0; c < 3 && c < mat.emissiveFactor.size(); ++c)
    out.emission[int(c)] =
        unit(mat.emissiveFactor[c]) *
        (strength >= 0 && std::isfinite(strength) && strength < 1e6 ? strength : 1.0);
  if (mat.emissiveTexture.index >= 0 && out.emission != color(0))
    out.emission_texture = image_texture(mat.emissiveTexture.index, texel_encoding::srgb, color(1),
                                         where + " emissiveTexture");
  if (mat.extensions.count("KHR_materials_unlit") != 0) {
    out.type = material_type::flat;  // the base color, as the extension's shading says
    return out;
  }
  out.type = material_type::pbr;
  read_pbr(mat, k, out.pbr, where);
  return out;
}

// A texture giving one of material k's parameters: the textureInfo's texture decoded in
// `encoding`, untinted (its factor is the parameter's own). The triangles carry one set of
// texture coordinates for every texture of a material but the emissive one (mapping(k)): a
// texture that reads another TEXCOORD_n or another KHR_texture_transform is drawn with those,
// and the scene's warnings say so, once per file, material and texture.
int gltf_materials::parameter_texture(const tinygltf::TextureInfo& info, texel_encoding encoding,
                                      std::size_t k, const std::string& where) {
  if (info.index < 0) return -1;
  const uv_mapping own = mapping_of(info);
  if (!mapped_[k]) {  // the material's first texture: the triangles carry its coordinates
    mappings_[k] = own;
    mapped_[k] = true;
  }
  if (own.set != mappings_[k].set || own.matrix != mappings_[k].matrix)
    b_.warn(where + ": reads TEXCOORD_" + std::to_string(own.set) +
            (own.matrix != glm::dmat3(1.0) ? " through its KHR_texture_transform" : "") +
            ", not the coordinates the triangles carry (TEXCOORD_" +
            std::to_string(mappings_[k].set) +
            " of the base color texture, as transformed "
            "there); drawn with those");
  return image_texture(info.index, encoding, color(1), where);
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
  // Data textures say so, that a dump reads them back as they were decoded; color ones keep the
  // default, in which a glTF's image (FILE#images/N) is read back: sRGB.
  if (encoding == texel_encoding::linear) tex.color_space = texel_encoding::linear;
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
