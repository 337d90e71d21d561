// The glTF reader against the Khronos sample models (tests/data/gltf, each with its license) and
// small files made here: textures per material use, accessors as the spec reads them, texture
// transforms, materials, extensions and the messages that name files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "errors.h"
#include "image_io.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
#include "process.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const std::filesystem::path gltf_data = RTVK_TEST_DATA_DIR "/gltf";

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The scene's image drawn unlit (every material flat, so the texels show as they are), `width`
// pixels square from the camera mesh_scene framed, 4 samples a pixel.
framebuffer unlit(scene s, int width) {
  for (named_material& m : s.materials) m.m.type = material_type::flat;
  s.render.width = width;
  s.render.aspect = 1;
  s.render.spp = 4;
  return render_cpu(test::scene_camera(s), s, s.render);
}

std::string str(const color& c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

// The channel of a color that is largest ("r", "g", "b"), or "gray" when none leads by 0.1.
std::string hue(const color& c) {
  const double top = std::max({c.r, c.g, c.b});
  const int n = (c.r > top - 0.1) + (c.g > top - 0.1) + (c.b > top - 0.1);
  if (n != 1) return n == 2 && c.b < top - 0.1 ? "yellow" : "gray";
  return c.r == top ? "r" : c.g == top ? "g" : "b";
}

// TextureCoordinateTest: four squares share one image, each material tinting it its own color
// (top left yellow, top right red, bottom left blue, bottom right green). The image was once made
// into one texture with the first material's tint, which drew all four blue.
TEST(GltfReader, EachMaterialTintsASharedImageItsOwnColor) {
  const scene s = mesh_scene(gltf_data / "TextureCoordinateTest/TextureCoordinateTest.glb");
  ASSERT_EQ(s.textures.size(), 4u);
  EXPECT_EQ(s.textures[0].image, s.textures[3].image);  // decoded once
  EXPECT_NE(s.textures[0].even, s.textures[3].even);
  const framebuffer fb = unlit(s, 64);
  EXPECT_EQ(hue(fb.at(20, 20)), "yellow") << str(fb.at(20, 20));
  EXPECT_EQ(hue(fb.at(44, 20)), "r") << str(fb.at(44, 20));
  EXPECT_EQ(hue(fb.at(20, 44)), "b") << str(fb.at(20, 44));
  EXPECT_EQ(hue(fb.at(44, 44)), "g") << str(fb.at(44, 44));
}

// One triangle whose accessors are given as JSON over one embedded buffer: the test's way to make
// any accessor layout. `attributes` and `accessors` are JSON members; `extra` more top-level ones.
std::string triangle_gltf(const std::string& bin, const std::string& attributes,
                          const std::string& accessors, const std::string& views,
                          const std::string& extra = "") {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
         R"("meshes":[{"primitives":[{"attributes":{)" +
         attributes + R"(},"material":0}]}],"materials":[{}],"buffers":[{"byteLength":)" +
         std::to_string(bin.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
         test::base64(bin) + R"("}],"bufferViews":[)" + views + R"(],"accessors":[)" + accessors +
         "]" + extra + "}";
}

template <typename T>
void put(std::string& bin, std::initializer_list<T> values) {
  for (T v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Normalized integers by the spec's formulas (BYTE: max(c / 127, -1), UNSIGNED_SHORT: c / 65535),
// read through a byteStride that pads each element to 4 bytes.
TEST(GltfReader, NormalizedIntegersAreScaledAsTheSpecSays) {
  std::string bin;
  put<std::int8_t>(bin, {-128, 0, 0, 0, 127, 0, 0, 0, 0, 127, 0, 0});
  put<std::uint16_t>(bin, {0, 65535, 65535, 32768, 0, 0});
  const scene s = [&] {
    scene out;
    load_mesh_bytes(out,
                    triangle_gltf(bin, R"("POSITION":0,"TEXCOORD_0":1)",
                                  R"({"bufferView":0,"componentType":5120,"normalized":true,)"
                                  R"("count":3,"type":"VEC3"},)"
                                  R"({"bufferView":1,"componentType":5123,"normalized":true,)"
                                  R"("count":3,"type":"VEC2"})",
                                  R"({"buffer":0,"byteLength":12,"byteStride":4},)"
                                  R"({"buffer":0,"byteOffset":12,"byteLength":12})"),
                    "gltf", "n.gltf", "", {});
    return out;
  }();
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].p[0], point3(-1, 0, 0));  // -128 / 127 clamped to -1
  EXPECT_EQ(s.triangles[0].p[1], point3(1, 0, 0));
  EXPECT_EQ(s.triangles[0].p[2], point3(0, 1, 0));
  const triangle_shading& sh = s.shading.at(std::size_t(s.triangles[0].shading));
  EXPECT_EQ(sh.uv[0], glm::dvec2(0, 0));  // v flipped: 1 - 65535 / 65535
  EXPECT_EQ(sh.uv[1], glm::dvec2(1, 1 - 32768 / 65535.0));
}

// SimpleSparseAccessor: three of fourteen positions replaced, lifting two bumps to y = 4 over a
// base that lies within y <= 1.
TEST(GltfReader, SparseAccessorsReplaceTheElementsTheyName) {
  const scene s = mesh_scene(gltf_data / "SimpleSparseAccessor/SimpleSparseAccessor.gltf");
  ASSERT_EQ(s.triangles.size(), 12u);
  double top = 0;
  for (const triangle& t : s.triangles)
    for (const point3& p : t.p) top = std::max(top, p.y);
  EXPECT_EQ(top, 4);
  // Out of order or out of range sparse indices are refused.
  std::string doc = read_file(gltf_data / "SimpleSparseAccessor/SimpleSparseAccessor.gltf");
  doc.replace(doc.find(R"("count": 3,)"), 10, R"("count": 4)");
  scene bad;
  try {
    load_mesh_bytes(bad, doc, "gltf", "s.gltf", "", {});
    ADD_FAILURE() << "a sparse accessor past its indices' view was read";
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find("sparse indices"), std::string::npos) << e.what();
  }
}

// Duck from glTF-Quantized (KHR_mesh_quantization: normalized BYTE normals, UNSIGNED_SHORT
// positions scaled by the node, UNSIGNED_SHORT texture coordinates scaled by
// KHR_texture_transform) is the plain Duck, to the quantization's step.
TEST(GltfReader, TheQuantizedDuckIsThePlainDuck) {
  const scene plain = mesh_scene(gltf_data / "Duck/Duck.gltf");
  const scene quantized = mesh_scene(gltf_data / "Duck/DuckQuantized.gltf");
  ASSERT_EQ(plain.triangles.size(), quantized.triangles.size());
  ASSERT_GT(plain.triangles.size(), 4000u);
  // gltfpack reordered the triangles and their corners: each quantized corner is compared with
  // the nearest corner of the plain triangle whose centroid is nearest.
  const auto centroid = [](const triangle& t) { return (t.p[0] + t.p[1] + t.p[2]) / 3.0; };
  double worst_p = 0, worst_uv = 0, worst_n = 0;
  for (const triangle& b : quantized.triangles) {
    const triangle* a = &plain.triangles[0];
    for (const triangle& c : plain.triangles)
      if (glm::length(centroid(c) - centroid(b)) < glm::length(centroid(*a) - centroid(b))) a = &c;
    const triangle_shading& sa = plain.shading.at(std::size_t(a->shading));
    const triangle_shading& sb = quantized.shading.at(std::size_t(b.shading));
    for (std::size_t k = 0; k < 3; ++k) {
      std::size_t j = 0;
      for (std::size_t c = 1; c < 3; ++c)
        if (glm::length(a->p[c] - b.p[k]) < glm::length(a->p[j] - b.p[k])) j = c;
      worst_p = std::max(worst_p, glm::length(a->p[j] - b.p[k]));
      worst_uv = std::max(worst_uv, glm::length(sa.uv[j] - sb.uv[k]));
      worst_n = std::max(worst_n,
                         glm::length(glm::normalize(sa.normal[j]) - glm::normalize(sb.normal[k])));
    }
  }
  // The duck is about 1.6 units across, quantized to 14 bits; its uv in steps of 2.3e-4 (half a
  // step on each axis: 1.7e-4); normals to 8 bits.
  EXPECT_LT(worst_p, 2e-4);
  EXPECT_LT(worst_uv, 2e-4);
  EXPECT_LT(worst_n, 2e-2);
  EXPECT_EQ(quantized.textures.at(0).image->texels, plain.textures.at(0).image->texels);
}

// A material's base color texture may read TEXCOORD_1 and map it by KHR_texture_transform (its
// own texCoord overriding the textureInfo's): offset, then rotation, then scale as the extension
// composes them, in glTF's uv, before v is flipped to rtvk's.
TEST(GltfReader, TextureTransformsAndCoordinateSetsMapTheUv) {
  std::string bin;
  put<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});  // positions
  put<float>(bin, {9, 9, 9, 9, 9, 9});           // TEXCOORD_0: not read
  put<float>(bin, {0, 0, 1, 0, 0, 1});           // TEXCOORD_1
  std::string doc =
      triangle_gltf(bin, R"("POSITION":0,"TEXCOORD_0":1,"TEXCOORD_1":2)",
                    R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                    R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},)"
                    R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC2"})",
                    R"({"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24},)"
                    R"({"buffer":0,"byteOffset":60,"byteLength":24})",
                    R"(,"textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" +
                        test::base64(encode_png(image_rgb8{1, 1, {255, 255, 255}})) + R"("}])");
  doc.replace(doc.find(R"("materials":[{}])"), 16,
              R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0,)"
              R"("texCoord":0,"extensions":{"KHR_texture_transform":{"texCoord":1,)"
              R"("offset":[0.5,0.25],"rotation":1.5707963267948966,"scale":[2,3]}}}}}])");
  scene s;
  load_mesh_bytes(s, doc, "gltf", "t.gltf", "", {});
  const triangle_shading& sh = s.shading.at(std::size_t(s.triangles.at(0).shading));
  // (1, 0) scaled to (2, 0), turned to (0, -2) (u' = cos u + sin v, v' = cos v - sin u), offset
  // to (0.5, -1.75), v flipped: (0.5, 2.75). (0, 1): (0, 3), (3, 0), (3.5, 0.25), (3.5, 0.75).
  EXPECT_NEAR(sh.uv[0].x, 0.5, 1e-12);
  EXPECT_NEAR(sh.uv[0].y, 0.75, 1e-12);
  EXPECT_NEAR(sh.uv[1].x, 0.5, 1e-12);
  EXPECT_NEAR(sh.uv[1].y, 2.75, 1e-12);
  EXPECT_NEAR(sh.uv[2].x, 3.5, 1e-12);
  EXPECT_NEAR(sh.uv[2].y, 0.75, 1e-12);
}

// A glTF material's fields as rtvk's (the renderer's side of them is not tested here): base color
// texture decoded as sRGB, alpha, cutoff, culling, emission times strength with its texture, and
// a metallicRoughnessTexture kept as a texture beside the factors (tests/scene/test_gltf_pbr.cpp
// holds the rest of the PBR parameters); the vertex colors of COLOR_0 (normalized UNSIGNED_BYTE
// VEC4).
TEST(GltfReader, MaterialsAndVertexColorsAreFilledIn) {
  std::string bin;
  put<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});
  put<std::uint8_t>(bin, {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0});
  const std::string png = encode_png(image_rgb8{2, 1, {188, 188, 188, 0, 30, 0}});
  std::string doc = triangle_gltf(
      bin, R"("POSITION":0,"COLOR_0":1)",
      R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
      R"({"bufferView":1,"componentType":5121,"normalized":true,"count":3,"type":"VEC4"})",
      R"({"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":12})",
      R"(,"textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" + test::base64(png) +
          R"("}])");
  doc.replace(doc.find(R"("materials":[{}])"), 16,
              R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},)"
              R"("baseColorFactor":[1,0.5,1,0.25],"metallicRoughnessTexture":{"index":0}},)"
              R"("alphaMode":"MASK","alphaCutoff":0.3,"emissiveFactor":[1,0.5,0],)"
              R"("emissiveTexture":{"index":0},"extensions":{"KHR_materials_emissive_strength":)"
              R"({"emissiveStrength":4}}},{"alphaMode":"BLEND","doubleSided":true}])");
  scene s;
  load_mesh_bytes(s, doc, "gltf", "m.gltf", "", {});
  ASSERT_EQ(s.materials.size(), 2u);
  const material& m = s.materials[0].m;
  // Issue 45: the PBR material, metallicFactor 1 (its default) per texel times the texture's blue
  // (glTF 2.0, 3.9.2: "the metalness values are sampled from the B channel"), no longer the
  // texture's mean deciding between rtvk's diffuse and metal kinds.
  EXPECT_EQ(m.type, material_type::pbr);
  EXPECT_EQ(m.pbr.metallic, 1);
  ASSERT_GE(m.pbr.metallic_roughness_texture, 0);
  EXPECT_EQ(s.textures[std::size_t(m.pbr.metallic_roughness_texture)].color_space,
            texel_encoding::linear);
  EXPECT_EQ(m.opacity, 0.25);
  EXPECT_EQ(m.alpha, alpha_mode::mask);
  EXPECT_EQ(m.alpha_cutoff, 0.3);
  EXPECT_TRUE(m.cull_back);
  EXPECT_EQ(m.emission, color(4, 2, 0));
  ASSERT_GE(m.texture, 0);
  ASSERT_GE(m.emission_texture, 0);
  const texture& base = s.textures[std::size_t(m.texture)];
  EXPECT_EQ(base.even, color(1, 0.5, 1));
  // 188 by the sRGB curve, ((188 / 255 + 0.055) / 1.055)^2.4, not the book's gamma 2.2.
  const double linear = std::pow((188 / 255.0 + 0.055) / 1.055, 2.4);
  EXPECT_EQ(base.image->texels[0] & 0xff, std::uint32_t(std::floor(256 * linear)));
  EXPECT_EQ(s.textures[std::size_t(m.emission_texture)].image, base.image);  // both sRGB
  EXPECT_EQ(s.materials[1].m.alpha, alpha_mode::blend);
  EXPECT_FALSE(s.materials[1].m.cull_back);
  // glTF's defaults: metallicFactor 1, roughnessFactor 1 (a rough metal, as the spec says).
  EXPECT_EQ(s.materials[1].m.type, material_type::pbr);
  EXPECT_EQ(s.materials[1].m.pbr.metallic, 1);
  EXPECT_EQ(s.materials[1].m.pbr.roughness, 1);
  const triangle_shading& sh = s.shading.at(std::size_t(s.triangles.at(0).shading));
  ASSERT_TRUE(sh.has_color);
  EXPECT_EQ(sh.color[0], glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(sh.color[1], glm::vec4(0, 1, 0, 128 / 255.f));
  EXPECT_EQ(sh.color[2], glm::vec4(0, 0, 1, 0));
}

void write(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// extensionsRequired: one rtvk cannot honour is refused by the CLI (exit 2, one line naming the
// file and the extension); the honoured ones load. Optional extensions it ignores, and the
// animations it does not play, are one warning line, said once on stderr however many times the
// file is placed.
TEST(GltfReader, RequiredExtensionsAreRefusedByNameAndIgnoredOnesWarnedOnce) {
  const test::temp_dir dir;
  const std::string doc = test::gltf_json(test::cube_sphere(1, 1.0));
  const auto with = [&](const std::string& members) {
    std::string d = doc;
    d.insert(1, members + ",");
    return d;
  };
  write(dir.path() / "req.gltf", with(R"("extensionsRequired":["KHR_draco_mesh_compression_x"],)"
                                      R"("extensionsUsed":["KHR_draco_mesh_compression_x"])"));
  write(
      dir.path() / "ok.gltf",
      with(
          R"("extensionsRequired":["KHR_mesh_quantization","KHR_texture_transform"],)"
          R"("extensionsUsed":["KHR_mesh_quantization","KHR_texture_transform",)"
          R"("KHR_materials_anisotropy","KHR_materials_iridescence"],"animations":[{"channels":[],)"
          R"("samplers":[]}])"));
  write(dir.path() / "s.json", R"({"meshes":[{"file":"ok.gltf"},{"file":"ok.gltf"}]})");
  const std::string out = (dir.path() / "o.png").string();
  const auto refused = test::run_rtvk(
      {"render", "--scene", (dir.path() / "req.gltf").string(), "-o", out, "--width", "8"});
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.err, "rtvk: " + (dir.path() / "req.gltf").string() +
                             ": extensionsRequired: KHR_draco_mesh_compression_x is not one rtvk "
                             "can draw\n");
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto drawn = test::run_rtvk({"render", "--scene", (dir.path() / "s.json").string(), "-o",
                                     out, "--width", "8", "--spp", "1"});
  EXPECT_EQ(drawn.status, 0) << drawn.err;
  const std::string warning =
      "rtvk: warning: " + (dir.path() / "ok.gltf").string() +
      ": drawn without what rtvk does not read: the extensions "
      "KHR_materials_anisotropy, KHR_materials_iridescence; 1 animation (drawn at "
      "rest)\n";
  EXPECT_EQ(drawn.err.find(warning), 0u) << drawn.err;
  EXPECT_EQ(drawn.err.rfind("warning"), drawn.err.find("warning")) << drawn.err;  // once
}

// A skin at rest: the triangle follows its joints' global transforms times their inverse bind
// matrices, blended by its weights, and its own node's transform (x + 100) is ignored as the spec
// says. Joint 0 (node 1) moves up 5; joint 1 (node 2, node 1's child) 2 more along x, times its
// inverse bind matrix (x - 1). Morph targets: the mesh's weight 0.5 of a target that moves z by 2.
TEST(GltfReader, SkinsAtRestAndMorphTargetsAtTheirWeightsMoveTheVertices) {
  std::string bin;
  put<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0});                  // POSITION
  put<std::uint8_t>(bin, {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0});  // JOINTS_0
  put<float>(bin, {1, 0, 0, 0, 0.5, 0.5, 0, 0, 1, 0, 0, 0});     // WEIGHTS_0
  put<float>(bin, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1,
                   1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1});  // inverse bind matrices
  put<float>(bin, {0, 0, 2, 0, 0, 2, 0, 0, 2});                        // the target's POSITION
  std::string doc = triangle_gltf(
      bin, R"("POSITION":0,"JOINTS_0":1,"WEIGHTS_0":2)",
      R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
      R"({"bufferView":1,"componentType":5121,"count":3,"type":"VEC4"},)"
      R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"},)"
      R"({"bufferView":3,"componentType":5126,"count":2,"type":"MAT4"},)"
      R"({"bufferView":4,"componentType":5126,"count":3,"type":"VEC3"})",
      R"({"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":12},)"
      R"({"buffer":0,"byteOffset":48,"byteLength":48},{"buffer":0,"byteOffset":96,"byteLength":128},)"
      R"({"buffer":0,"byteOffset":224,"byteLength":36})",
      R"(,"skins":[{"joints":[1,2],"inverseBindMatrices":3}])");
  doc.replace(doc.find(R"("nodes":[{"mesh":0}])"), 20,
              R"("nodes":[{"mesh":0,"skin":0,"translation":[100,0,0]},)"
              R"({"translation":[0,5,0],"children":[2]},{"translation":[2,0,0]}])");
  doc.replace(doc.find(R"("scenes":[{"nodes":[0]}])"), 24, R"("scenes":[{"nodes":[0,1]}])");
  doc.replace(doc.find(R"(,"material":0)"), 0, R"(,"targets":[{"POSITION":4}])");
  doc.replace(doc.find(R"("meshes":[{)"), 11, R"("meshes":[{"weights":[0.5],)");
  scene s;
  load_mesh_bytes(s, doc, "gltf", "k.gltf", "", {});
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].p[0], point3(0, 5, 1));    // joint 0: (0, 5, 0)
  EXPECT_EQ(s.triangles[0].p[1], point3(1.5, 5, 1));  // half joint 0, half joint 1: + (0.5, 0, 0)
  EXPECT_EQ(s.triangles[0].p[2], point3(1, 6, 1));    // joint 1: + (2 - 1, 5, 0)
}

// MorphPrimitivesTest: two primitives (a red grid over three quadrants, a green one over the
// fourth) whose morph targets, at the mesh's weight 0.5, raise the middle; flat if they are not
// applied. Both tint one image, each its own color.
TEST(GltfReader, MorphPrimitivesTestIsRaisedAndTintedPerPrimitive) {
  const scene s = mesh_scene(gltf_data / "MorphPrimitivesTest/MorphPrimitivesTest.glb");
  point3 lo(1e30), hi(-1e30);
  for (const triangle& t : s.triangles)
    for (const point3& p : t.p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double width = std::max(hi.x - lo.x, hi.z - lo.z);
  const double height = std::min(hi.y - lo.y, std::min(hi.x - lo.x, hi.z - lo.z));
  EXPECT_GT(height, 0.05 * width) << "flat: the morph targets were not applied";
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.textures[0].image, s.textures[1].image);
  EXPECT_EQ(s.textures[0].even, color(1, 0, 0));
  EXPECT_EQ(s.textures[1].even, color(0, 1, 0));
}

// What mesh_scene's refusal says ("" when it loads).
std::string refusal_of(const std::filesystem::path& file) {
  try {
    mesh_scene(file);
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}

// Files that are not what they should be, each said in one short line naming the file: a missing
// .bin or image (the path looked for), a git-lfs pointer or an HTML page saved in a glTF's or a
// buffer's place, a bad data URI (cut, not printed whole).
TEST(GltfReader, BrokenFilesAreSaidInOneLineNamingTheFile) {
  const test::temp_dir dir;
  const std::filesystem::path d = dir.path();
  const std::string duck = read_file(gltf_data / "Duck/Duck.gltf");
  write(d / "Duck.gltf", duck);
  EXPECT_EQ(refusal_of(d / "Duck.gltf"), (d / "Duck.gltf").string() + ": " +
                                             (d / "Duck0.bin").string() +
                                             " not found (a file the glTF names)");
  const std::string pointer =
      "version https://git-lfs.github.com/spec/v1\noid sha256:4d7a21\nsize 102040\n";
  write(d / "Duck0.bin", pointer);
  EXPECT_EQ(refusal_of(d / "Duck.gltf"),
            (d / "Duck.gltf").string() + ": " + (d / "Duck0.bin").string() +
                " is a git-lfs pointer, not the file (fetch it with git lfs pull)");
  write(d / "Duck0.bin", read_file(gltf_data / "Duck/Duck0.bin"));
  EXPECT_EQ(refusal_of(d / "Duck.gltf"), (d / "Duck.gltf").string() +
                                             ": materials 0 baseColorTexture: image 0: " +
                                             (d / "DuckCM.png").string() + " not found");
  write(d / "p.glb", pointer);
  EXPECT_EQ(refusal_of(d / "p.glb"), (d / "p.glb").string() +
                                         ": a git-lfs pointer, not the file (fetch it with git "
                                         "lfs pull)");
  write(d / "h.glb", "\n<!DOCTYPE html>\n<html lang=\"en\"><body>Duck.glb</body></html>");
  EXPECT_EQ(refusal_of(d / "h.glb").find((d / "h.glb").string() + ": an HTML page"), 0u)
      << refusal_of(d / "h.glb");
  std::string bad = duck;
  bad.replace(bad.find("Duck0.bin"), 9,
              "data:application/octet-stream;base64," + std::string(100000, '!'));
  write(d / "b.gltf", bad);
  const std::string said = refusal_of(d / "b.gltf");
  EXPECT_LT(said.size(), 300u) << said;
  EXPECT_NE(said.find("a data URI of 100037 characters"), std::string::npos) << said;
}

}  // namespace
}  // namespace rtvk
