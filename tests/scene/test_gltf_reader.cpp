// The glTF reader against the Khronos sample models (tests/data/gltf, each with its license) and
// small files made here: textures per material use, accessors as the spec reads them, texture
// transforms, materials, extensions and the messages that name files.
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
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

}  // namespace
}  // namespace rtvk
