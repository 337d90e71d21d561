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

}  // namespace
}  // namespace rtvk
