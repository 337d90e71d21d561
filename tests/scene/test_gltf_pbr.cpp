// glTF materials as rtvk's pbr material (issue 45; docs/mesh-formats.md's table): every
// parameter of pbrMetallicRoughness and of the KHR_materials_* extensions read exactly as the file
// gives it, each texture in its color space and channel, the ranges the specifications give
// refused outside them (exit 2), and the extensions rtvk does not draw refused or listed by name.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "errors.h"
#include "image_io.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
#include "process.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

using nlohmann::json;

// One triangle with two sets of texture coordinates, its material `material`, and images 0 and 1:
// 1x1 PNGs of (188, 100, 50) and (20, 40, 60), each the source of the texture of its index.
std::string pbr_gltf(const json& material, const json& top = json::object()) {
  std::string bin;
  const auto put = [&bin](float f) { bin.append(reinterpret_cast<const char*>(&f), 4); };
  for (float p : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(p);
  for (float t : {0.f, 0.f, 1.f, 0.f, 0.f, 1.f}) put(t);
  for (float t : {0.5f, 0.5f, 1.f, 0.5f, 0.5f, 1.f}) put(t);
  const auto png = [](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return "data:image/png;base64," + test::base64(encode_png(image_rgb8{1, 1, {r, g, b}}));
  };
  json doc = {{"asset", {{"version", "2.0"}}},
              {"scene", 0},
              {"scenes", {{{"nodes", {0}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"meshes",
               {{{"primitives",
                  {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 2}}},
                    {"material", 0}}}}}}},
              {"materials", {material}},
              {"textures", {{{"source", 0}}, {{"source", 1}}}},
              {"images", {{{"uri", png(188, 100, 50)}}, {{"uri", png(20, 40, 60)}}}},
              {"buffers",
               {{{"byteLength", bin.size()},
                 {"uri", "data:application/octet-stream;base64," + test::base64(bin)}}}},
              {"bufferViews",
               {{{"buffer", 0}, {"byteLength", 36}},
                {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}},
                {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 24}}}},
              {"accessors",
               {{{"bufferView", 0},
                 {"componentType", 5126},
                 {"count", 3},
                 {"type", "VEC3"},
                 {"min", {0, 0, 0}},
                 {"max", {1, 1, 0}}},
                {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}},
                {{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
  doc.update(top);
  return doc.dump();
}

void write(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

scene loaded(const json& material, const json& top = json::object()) {
  scene s;
  load_mesh_bytes(s, pbr_gltf(material, top), "gltf", "m.gltf", "", {});
  return s;
}

// The refusal a material's file meets, or "" where it loads.
std::string refusal(const json& material) {
  try {
    loaded(material);
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}

// Texture t of the scene: decoded in `space` (its first texel's red byte: 188 as data, the sRGB
// curve's 128 as a color), and marked so for a dump where it is data.
void expect_space(const scene& s, int t, texel_encoding space, const std::string& what) {
  ASSERT_GE(t, 0) << what;
  ASSERT_LT(std::size_t(t), s.textures.size()) << what;
  const texture& tex = s.textures[std::size_t(t)];
  const std::uint32_t red = tex.image->texels.at(0) & 0xff;
  if (space == texel_encoding::linear) {
    EXPECT_TRUE(red == 188 || red == 20) << what << ": " << red;
    EXPECT_EQ(tex.color_space, texel_encoding::linear) << what;
  } else {
    const double linear = std::pow((188 / 255.0 + 0.055) / 1.055, 2.4);
    const double dark = std::pow((20 / 255.0 + 0.055) / 1.055, 2.4);
    EXPECT_TRUE(red == std::uint32_t(std::floor(256 * linear)) ||
                red == std::uint32_t(std::floor(256 * dark)))
        << what << ": " << red;
  }
  EXPECT_EQ(tex.even, color(1)) << what;  // untinted: the factor is the parameter's own
}

// pbrMetallicRoughness and normalTexture, each exactly as written; occlusionTexture not read
// (no texture made for it); a material with none of them has glTF's defaults.
TEST(GltfPbr, MetallicRoughnessAndNormalMapAreReadExactly) {
  const scene s = loaded({{"pbrMetallicRoughness",
                           {{"baseColorFactor", {0.5, 0.25, 1, 1}},
                            {"baseColorTexture", {{"index", 1}}},
                            {"metallicFactor", 0.375},
                            {"roughnessFactor", 0.625},
                            {"metallicRoughnessTexture", {{"index", 0}}}}},
                          {"normalTexture", {{"index", 0}, {"scale", 0.75}}},
                          {"occlusionTexture", {{"index", 1}}}});
  ASSERT_EQ(s.materials.size(), 1u);
  const material& m = s.materials[0].m;
  EXPECT_EQ(m.type, material_type::pbr);
  EXPECT_EQ(m.albedo, color(0.5, 0.25, 1));
  EXPECT_EQ(m.pbr.metallic, 0.375);
  EXPECT_EQ(m.pbr.roughness, 0.625);
  EXPECT_EQ(m.pbr.normal_scale, 0.75);
  EXPECT_EQ(s.textures.size(), 3u);  // base color, metallic-roughness, normal: no occlusion
  EXPECT_EQ(s.textures[std::size_t(m.texture)].even, color(0.5, 0.25, 1));
  expect_space(s, m.pbr.metallic_roughness_texture, texel_encoding::linear, "metallicRoughness");
  expect_space(s, m.pbr.normal_texture, texel_encoding::linear, "normal");
  // One image decoded once per color space, shared by its data textures.
  EXPECT_EQ(s.textures[std::size_t(m.pbr.normal_texture)].image,
            s.textures[std::size_t(m.pbr.metallic_roughness_texture)].image);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();

  const pbr_material defaults{};
  // The scene is kept: a reference into a temporary's materials would dangle.
  const scene plain = loaded(json::object());
  const pbr_material& d = plain.materials[0].m.pbr;
  EXPECT_EQ(plain.materials[0].m.type, material_type::pbr);
  EXPECT_EQ(d.metallic, 1);  // glTF's defaults: metallicFactor 1, roughnessFactor 1
  EXPECT_EQ(d.roughness, 1);
  EXPECT_EQ(d.ior, defaults.ior);
  EXPECT_EQ(d.specular, defaults.specular);
  EXPECT_EQ(d.transmission, 0);
  EXPECT_EQ(d.attenuation_distance, defaults.attenuation_distance);
  EXPECT_EQ(d.sheen_color, color(0));
  EXPECT_EQ(d.metallic_roughness_texture, -1);
  EXPECT_EQ(d.normal_texture, -1);
}

// Every extension rtvk reads, every field set away from its default: each lands in its own
// parameter, each texture in its color space (specularColor and sheenColor sRGB, the rest data).
TEST(GltfPbr, EveryExtensionIsReadExactly) {
  const json t0 = {{"index", 0}}, t1 = {{"index", 1}};
  const scene s = loaded(
      {{"extensions",
        {{"KHR_materials_ior", {{"ior", 1.25}}},
         {"KHR_materials_specular",
          {{"specularFactor", 0.3},
           {"specularTexture", t0},
           {"specularColorFactor", {0.5, 0.75, 2}},
           {"specularColorTexture", t0}}},
         {"KHR_materials_transmission", {{"transmissionFactor", 0.8}, {"transmissionTexture", t1}}},
         {"KHR_materials_volume",
          {{"thicknessFactor", 0.125},
           {"thicknessTexture", t0},
           {"attenuationColor", {0.25, 0.5, 0.75}},
           {"attenuationDistance", 2.5}}},
         {"KHR_materials_clearcoat",
          {{"clearcoatFactor", 0.6},
           {"clearcoatTexture", t0},
           {"clearcoatRoughnessFactor", 0.2},
           {"clearcoatRoughnessTexture", t1},
           {"clearcoatNormalTexture", {{"index", 1}, {"scale", 0.5}}}}},
         {"KHR_materials_sheen",
          {{"sheenColorFactor", {0.1, 0.2, 0.3}},
           {"sheenColorTexture", t1},
           {"sheenRoughnessFactor", 0.4},
           {"sheenRoughnessTexture", t0}}}}}},
      {{"extensionsUsed",
        {"KHR_materials_ior", "KHR_materials_specular", "KHR_materials_transmission",
         "KHR_materials_volume", "KHR_materials_clearcoat", "KHR_materials_sheen"}},
       {"extensionsRequired", {"KHR_materials_volume", "KHR_materials_clearcoat"}}});
  const material& m = s.materials.at(0).m;
  const pbr_material& p = m.pbr;
  EXPECT_EQ(m.type, material_type::pbr);
  EXPECT_EQ(p.ior, 1.25);
  EXPECT_EQ(p.specular, 0.3);
  EXPECT_EQ(p.specular_color, color(0.5, 0.75, 2));  // the spec sets no maximum
  EXPECT_EQ(p.transmission, 0.8);
  EXPECT_EQ(p.thickness, 0.125);
  EXPECT_EQ(p.attenuation_color, color(0.25, 0.5, 0.75));
  EXPECT_EQ(p.attenuation_distance, 2.5);
  EXPECT_EQ(p.clearcoat, 0.6);
  EXPECT_EQ(p.clearcoat_roughness, 0.2);
  EXPECT_EQ(p.clearcoat_normal_scale, 0.5);
  EXPECT_EQ(p.sheen_color, color(0.1, 0.2, 0.3));
  EXPECT_EQ(p.sheen_roughness, 0.4);
  const texel_encoding linear = texel_encoding::linear, srgb = texel_encoding::srgb;
  expect_space(s, p.specular_texture, linear, "specularTexture");
  expect_space(s, p.specular_color_texture, srgb, "specularColorTexture");
  expect_space(s, p.transmission_texture, linear, "transmissionTexture");
  expect_space(s, p.thickness_texture, linear, "thicknessTexture");
  expect_space(s, p.clearcoat_texture, linear, "clearcoatTexture");
  expect_space(s, p.clearcoat_roughness_texture, linear, "clearcoatRoughnessTexture");
  expect_space(s, p.clearcoat_normal_texture, linear, "clearcoatNormalTexture");
  expect_space(s, p.sheen_color_texture, srgb, "sheenColorTexture");
  expect_space(s, p.sheen_roughness_texture, linear, "sheenRoughnessTexture");
  // Each use its own texture (its own tint and sampler), the images decoded once per color
  // space: image 0 as data and as a color, image 1 likewise.
  EXPECT_EQ(s.textures.size(), 9u);
  EXPECT_EQ(s.textures[std::size_t(p.specular_texture)].image,
            s.textures[std::size_t(p.clearcoat_texture)].image);
  EXPECT_NE(s.textures[std::size_t(p.specular_texture)].image,
            s.textures[std::size_t(p.specular_color_texture)].image);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  // KHR_materials_ior's special case: 0, the Fresnel term 1.
  EXPECT_EQ(loaded({{"extensions", {{"KHR_materials_ior", {{"ior", 0}}}}}}).materials[0].m.pbr.ior,
            0);
}

// KHR_materials_unlit: rtvk's unlit kind (flat) of the base color, its texture and alpha kept.
TEST(GltfPbr, UnlitMaterialsAreFlat) {
  const scene s =
      loaded({{"pbrMetallicRoughness",
               {{"baseColorFactor", {0.2, 0.4, 0.6, 0.5}}, {"baseColorTexture", {{"index", 0}}}}},
              {"alphaMode", "BLEND"},
              {"extensions", {{"KHR_materials_unlit", json::object()}}}},
             {{"extensionsUsed", {"KHR_materials_unlit"}},
              {"extensionsRequired", {"KHR_materials_unlit"}}});
  const material& m = s.materials.at(0).m;
  EXPECT_EQ(m.type, material_type::flat);
  EXPECT_EQ(m.albedo, color(0.2, 0.4, 0.6));
  EXPECT_EQ(m.opacity, 0.5);
  EXPECT_EQ(m.alpha, alpha_mode::blend);
  ASSERT_GE(m.texture, 0);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

// Each factor outside the range its specification gives is refused, naming the material, the
// object, the field and the value (the CLI's exit 2).
TEST(GltfPbr, FactorsOutsideTheirSpecificationsRangesAreRefused) {
  const auto ext = [](const char* name, const json& fields) {
    return json{{"extensions", {{name, fields}}}};
  };
  const std::pair<json, std::string> cases[] = {
      {{{"pbrMetallicRoughness", {{"metallicFactor", 2}}}},
       "m.gltf: materials 0 pbrMetallicRoughness metallicFactor: must be in [0, 1], got 2"},
      {{{"pbrMetallicRoughness", {{"roughnessFactor", -0.5}}}},
       "m.gltf: materials 0 pbrMetallicRoughness roughnessFactor: must be in [0, 1], got -0.5"},
      {ext("KHR_materials_ior", {{"ior", 0.5}}),
       "m.gltf: materials 0 KHR_materials_ior ior: must be >= 1 or 0, got 0.5"},
      {ext("KHR_materials_ior", {{"ior", -1}}),
       "m.gltf: materials 0 KHR_materials_ior ior: must be >= 1 or 0, got -1"},
      {ext("KHR_materials_specular", {{"specularFactor", 1.5}}),
       "m.gltf: materials 0 KHR_materials_specular specularFactor: must be in [0, 1], got 1.5"},
      {ext("KHR_materials_specular", {{"specularColorFactor", {1, -1, 1}}}),
       "m.gltf: materials 0 KHR_materials_specular specularColorFactor[1]: must be >= 0, got -1"},
      {ext("KHR_materials_transmission", {{"transmissionFactor", "all"}}),
       "m.gltf: materials 0 KHR_materials_transmission transmissionFactor: expected a number"},
      {ext("KHR_materials_volume", {{"attenuationDistance", -1}}),
       "m.gltf: materials 0 KHR_materials_volume attenuationDistance: must be > 0, got -1"},
      {ext("KHR_materials_volume", {{"attenuationDistance", 0}}),
       "m.gltf: materials 0 KHR_materials_volume attenuationDistance: must be > 0, got 0"},
      {ext("KHR_materials_volume", {{"thicknessFactor", -0.1}}),
       "m.gltf: materials 0 KHR_materials_volume thicknessFactor: must be >= 0, got -0.1"},
      {ext("KHR_materials_volume", {{"attenuationColor", {1, 1}}}),
       "m.gltf: materials 0 KHR_materials_volume attenuationColor: expected an array of 3 "
       "numbers"},
      {ext("KHR_materials_clearcoat", {{"clearcoatRoughnessFactor", 3}}),
       "m.gltf: materials 0 KHR_materials_clearcoat clearcoatRoughnessFactor: must be in [0, 1], "
       "got 3"},
      {ext("KHR_materials_clearcoat", {{"clearcoatTexture", {{"index", 7}}}}),
       "m.gltf: materials 0 KHR_materials_clearcoat clearcoatTexture: texture 7 does not exist"},
      {ext("KHR_materials_sheen", {{"sheenColorFactor", {2, 0, 0}}}),
       "m.gltf: materials 0 KHR_materials_sheen sheenColorFactor[0]: must be in [0, 1], got 2"},
      {ext("KHR_materials_sheen", {{"sheenRoughnessTexture", {{"texCoord", 1}}}}),
       "m.gltf: materials 0 KHR_materials_sheen sheenRoughnessTexture: expected a textureInfo "
       "with an index"},
  };
  for (const auto& [material, message] : cases) EXPECT_EQ(refusal(material), message);
  EXPECT_EQ(refusal(ext("KHR_materials_ior", {{"ior", 1}})), "");  // the bounds themselves
  EXPECT_EQ(refusal({{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}}}),
            "");
}

// KHR_materials_iridescence, _anisotropy and _dispersion are not drawn: required, the file is
// refused by name (exit 2, no image); only used, they are listed in the file's one warning.
TEST(GltfPbr, UndrawnMaterialExtensionsAreRefusedWhereRequiredAndListedWhereUsed) {
  const test::temp_dir dir;
  const json iridescent = {{"extensions", {{"KHR_materials_iridescence", json::object()}}}};
  write(dir.path() / "req.gltf",
        pbr_gltf(iridescent, {{"extensionsUsed", {"KHR_materials_iridescence"}},
                              {"extensionsRequired", {"KHR_materials_iridescence"}}}));
  const std::string out = (dir.path() / "o.png").string();
  const auto refused = test::run_rtvk(
      {"render", "--scene", (dir.path() / "req.gltf").string(), "-o", out, "--width", "8"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.err, "rtvk: " + (dir.path() / "req.gltf").string() +
                             ": extensionsRequired: KHR_materials_iridescence is not one rtvk "
                             "can draw\n");
  EXPECT_FALSE(std::filesystem::exists(out));
  const scene s = loaded(iridescent, {{"extensionsUsed",
                                       {"KHR_materials_iridescence", "KHR_materials_anisotropy",
                                        "KHR_materials_sheen", "KHR_materials_dispersion"}}});
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0],
            "m.gltf: drawn without what rtvk does not read: the extensions "
            "KHR_materials_iridescence, KHR_materials_anisotropy, KHR_materials_dispersion");
}

// The triangles carry one set of texture coordinates for a material's textures (but the
// emissive one's): the base color's, else the first texture's. A parameter texture reading
// another set or transform is drawn with those, and the warnings say so once.
TEST(GltfPbr, ParameterTexturesOnOtherCoordinatesAreWarned) {
  const json normal_on_1 = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                            {"normalTexture", {{"index", 1}, {"texCoord", 1}}}};
  scene s = loaded(normal_on_1);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0],
            "m.gltf: materials 0 normalTexture: reads TEXCOORD_1, not the coordinates the "
            "triangles carry (TEXCOORD_0 of the base color texture, as transformed there); drawn "
            "with those");
  load_mesh_bytes(s, pbr_gltf(normal_on_1), "gltf", "m.gltf", "", {});  // placed twice: once
  EXPECT_EQ(s.warnings.size(), 1u);
  const json moved = {
      {"pbrMetallicRoughness",
       {{"baseColorTexture", {{"index", 0}}},
        {"metallicRoughnessTexture",
         {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0}}}}}}}}}}};
  const scene t = loaded(moved);
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("metallicRoughnessTexture: reads TEXCOORD_0 through its "
                               "KHR_texture_transform"),
            std::string::npos)
      << t.warnings[0];
  // No base color texture: the first parameter texture's set is the triangles' (TEXCOORD_1:
  // its first corner (0.5, 0.5), v flipped), and one on the same set is no warning.
  const scene u = loaded(
      {{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 0}, {"texCoord", 1}}}}},
       {"normalTexture", {{"index", 1}, {"texCoord", 1}}}});
  EXPECT_TRUE(u.warnings.empty()) << u.warnings.front();
  const triangle_shading& sh = u.shading.at(std::size_t(u.triangles.at(0).shading));
  EXPECT_EQ(sh.uv[0], glm::dvec2(0.5, 0.5));
  EXPECT_EQ(sh.uv[1], glm::dvec2(1, 0.5));
}

// A data texture is marked linear, so that a dump names it FILE#images/N with "color_space":
// "linear" and a scene file reads it back as data: the same bytes, not the sRGB curve's (it read
// every glTF image back as sRGB before).
TEST(GltfPbr, AGltfImageNamedLinearInASceneFileIsReadAsData) {
  const test::temp_dir dir;
  write(dir.path() / "m.gltf", pbr_gltf(json::object()));
  const auto texel = [&](const char* space) {
    write(dir.path() / "s.json",
          std::string(R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image",)") +
              R"("file":"m.gltf#images/0","color_space":")" + space +
              R"("}}},"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]})");
    const scene s = load_scene_file(dir.path() / "s.json");
    return s.textures.at(0).image->texels.at(0) & 0xffu;
  };
  EXPECT_EQ(texel("linear"), 188u);
  EXPECT_EQ(texel("srgb"),
            std::uint32_t(std::floor(256 * std::pow((188 / 255.0 + 0.055) / 1.055, 2.4))));
}

}  // namespace
}  // namespace rtvk
