// Scene files' `"type": "pbr"` materials: every pbr_material parameter by its name, a texture
// wherever a map may be, ranges refused naming the field and the value (exit 2), and `rtvk scene
// dump` writing them back so that the dump reloads to the same scene.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <tuple>

#include "errors.h"
#include "process.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const char* every_parameter = R"({"materials":{
  "p":{"type":"pbr","albedo":[0.5,0.25,0.125],"metallic":0.25,"roughness":0.75,
       "normal_scale":0.5,"ior":1.33,"specular":0.5,"specular_color":[1.5,1,0.5],
       "transmission":0.875,"thickness":0.2,"attenuation_color":[0.9,0.5,0.1],
       "attenuation_distance":3,"clearcoat":0.625,"clearcoat_roughness":0.125,
       "clearcoat_normal_scale":2,"sheen_color":[0.3,0.2,0.1],"sheen_roughness":0.375,
       "metallic_roughness_texture":{"type":"checker","scale":0.5,"even":[1,1,1],"odd":[0,0.5,1]},
       "sheen_color_texture":{"type":"noise","scale":2},
       "emission":[1,2,3],"alpha_mode":"mask"},
  "plain":{"type":"pbr","albedo":{"type":"checker","even":[1,1,1],"odd":[0,0,0]}}},
  "spheres":[{"center":[0,0,0],"radius":1,"material":"p"}]})";

TEST(SceneFilePbr, EveryParameterIsReadByItsName) {
  const scene s = parse_scene_json(every_parameter, "pbr.json");
  ASSERT_EQ(s.materials.size(), 2u);
  const material& m = s.materials[0].m;
  EXPECT_EQ(m.type, material_type::pbr);
  EXPECT_EQ(m.albedo, color(0.5, 0.25, 0.125));
  const pbr_material& q = m.pbr;
  EXPECT_EQ(q.metallic, 0.25);
  EXPECT_EQ(q.roughness, 0.75);
  EXPECT_EQ(q.normal_scale, 0.5);
  EXPECT_EQ(q.ior, 1.33);
  EXPECT_EQ(q.specular, 0.5);
  EXPECT_EQ(q.specular_color, color(1.5, 1, 0.5));
  EXPECT_EQ(q.transmission, 0.875);
  EXPECT_EQ(q.thickness, 0.2);
  EXPECT_EQ(q.attenuation_color, color(0.9, 0.5, 0.1));
  EXPECT_EQ(q.attenuation_distance, 3);
  EXPECT_EQ(q.clearcoat, 0.625);
  EXPECT_EQ(q.clearcoat_roughness, 0.125);
  EXPECT_EQ(q.clearcoat_normal_scale, 2);
  EXPECT_EQ(q.sheen_color, color(0.3, 0.2, 0.1));
  EXPECT_EQ(q.sheen_roughness, 0.375);
  ASSERT_EQ(s.textures.size(), 3u);
  EXPECT_EQ(q.metallic_roughness_texture, 0);
  EXPECT_EQ(s.textures[0].odd, color(0, 0.5, 1));
  EXPECT_EQ(q.sheen_color_texture, 1);
  EXPECT_EQ(q.normal_texture, -1);
  EXPECT_EQ(m.emission, color(1, 2, 3));
  EXPECT_EQ(m.alpha, alpha_mode::mask);
  // The defaults are glTF's: an absent attenuation_distance is infinite.
  const pbr_material& d = s.materials[1].m.pbr;
  EXPECT_EQ(d.metallic, 1);
  EXPECT_EQ(d.roughness, 1);
  EXPECT_EQ(d.ior, 1.5);
  EXPECT_EQ(d.attenuation_distance, std::numeric_limits<double>::infinity());
  EXPECT_EQ(s.materials[1].m.texture, 2);
}

// Every field of two PBR materials alike.
bool same(const pbr_material& a, const pbr_material& b) {
  const auto fields = [](const pbr_material& q) {
    return std::tie(q.metallic, q.roughness, q.metallic_roughness_texture, q.normal_texture,
                    q.normal_scale, q.ior, q.specular, q.specular_texture, q.specular_color,
                    q.specular_color_texture, q.transmission, q.transmission_texture, q.thickness,
                    q.thickness_texture, q.attenuation_color, q.attenuation_distance, q.clearcoat,
                    q.clearcoat_texture, q.clearcoat_roughness, q.clearcoat_roughness_texture,
                    q.clearcoat_normal_texture, q.clearcoat_normal_scale, q.sheen_color,
                    q.sheen_color_texture, q.sheen_roughness, q.sheen_roughness_texture);
  };
  return fields(a) == fields(b);
}

// A dumped file reloads to the same scene: every parameter, both textures and the defaults.
TEST(SceneFilePbr, ADumpReloadsToTheSameScene) {
  const scene s = parse_scene_json(every_parameter, "pbr.json");
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("\"type\":\"pbr\""), std::string::npos) << dumped;
  EXPECT_NE(dumped.find("\"sheen_color_texture\""), std::string::npos) << dumped;
  const scene back = parse_scene_json(dumped, "back.json");
  ASSERT_EQ(back.materials.size(), s.materials.size());
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    const material& a = s.materials[k].m;
    const material& b = back.materials[k].m;
    EXPECT_EQ(b.type, a.type);
    EXPECT_EQ(b.albedo, a.albedo);
    EXPECT_EQ(b.texture, a.texture);
    EXPECT_EQ(b.emission, a.emission);
    EXPECT_TRUE(same(b.pbr, a.pbr)) << s.materials[k].name;
  }
  EXPECT_EQ(dump_scene_json(back), dumped);
}

// Each range refused with a one-line message naming the field and the value.
TEST(SceneFilePbr, ValuesOutOfRangeNameTheFieldAndTheValue) {
  const struct {
    const char* field;
    const char* value;
    const char* says;
  } bad[] = {
      {"metallic", "1.5", "/materials/p/metallic: expected a number in [0, 1], got 1.5"},
      {"roughness", "-0.25", "/materials/p/roughness: expected a number in [0, 1], got -0.25"},
      {"ior", "0.5", "/materials/p/ior: expected a number in [1, 100], got 0.5"},
      {"transmission", "2", "/materials/p/transmission: expected a number in [0, 1], got 2"},
      {"thickness", "-1", "/materials/p/thickness: expected a number in [0, 1e+30], got -1"},
      {"attenuation_distance", "0", "/materials/p/attenuation_distance: expected a distance > 0"},
      {"attenuation_color", "[1,2,0]", "/materials/p/attenuation_color"},
      {"sheen_roughness", "\"rough\"", "/materials/p/sheen_roughness: expected a number"},
      {"clearcoat_texture", "[1,1,1]", "/materials/p/clearcoat_texture: expected a texture"},
      {"fuzz", "0.5", "/materials/p"},  // a metal's field: not a PBR material's
  };
  for (const auto& b : bad) {
    const std::string text = std::string(R"({"materials":{"p":{"type":"pbr","albedo":[1,1,1],")") +
                             b.field + "\":" + b.value + "}}}";
    std::string e = "no error";
    try {
      parse_scene_json(text, "bad.json");
    } catch (const usage_error& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(b.says), std::string::npos) << b.field << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

// The executable exits 2 on such a file, naming the field, and writes no image.
TEST(SceneFilePbr, TheCliExitsTwoNamingTheField) {
  test::temp_dir dir;
  const auto file = dir.path() / "bad.json";
  std::ofstream(file) << R"({"materials":{"p":{"type":"pbr","albedo":[1,1,1],"metallic":3}},)"
                      << R"("spheres":[{"center":[0,0,-1],"radius":0.5,"material":"p"}]})";
  const auto out = dir.path() / "out.png";
  const test::process_result r = test::run_rtvk(
      {"render", "--scene", file.string(), "--backend", "cpu", "--output", out.string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/materials/p/metallic"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("got 3"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rtvk
