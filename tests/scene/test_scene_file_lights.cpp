// Scene files' "lights" (point, spot, directional, sun): every field read by its name, `rtvk scene
// dump` writing them back so that the dump reloads to the same lights, and bad values refused
// with one line naming the field and the value (exit 2, no image).
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "process.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const std::string sphere_part = R"("materials":{"m":{"type":"lambertian","albedo":[0.5,0.5,0.5]}},)"
                                R"("spheres":[{"center":[0,0,-1],"radius":0.5,"material":"m"}])";

std::string with_lights(const std::string& lights) {
  return "{" + sphere_part + R"(,"lights":[)" + lights + "]}";
}

const std::string every_kind = with_lights(
    R"({"type":"point","name":"bulb","position":[1,2,3],"color":[1,0.5,0.25],"intensity":40},)"
    R"({"type":"spot","position":[0,4,0],"direction":[0,-1,0],"intensity":100,)"
    R"("inner_cone_angle":10,"outer_cone_angle":30},)"
    R"({"type":"directional","direction":[1,-2,0.5],"intensity":3},)"
    R"({"type":"directional","direction":[0,-1,0],"intensity":100000,"angular_diameter":0.53})");

TEST(SceneFileLights, EveryFieldIsReadByItsName) {
  const scene s = parse_scene_json(every_kind, "lights.json");
  ASSERT_EQ(s.punctual_lights.size(), 4u);
  const punctual_light& bulb = s.punctual_lights[0];
  EXPECT_EQ(bulb.kind, punctual_kind::point);
  EXPECT_EQ(bulb.name, "bulb");
  EXPECT_EQ(bulb.position, point3(1, 2, 3));
  EXPECT_EQ(bulb.tint, color(1, 0.5, 0.25));
  EXPECT_EQ(bulb.intensity, 40);
  const punctual_light& spot = s.punctual_lights[1];
  EXPECT_EQ(spot.kind, punctual_kind::spot);
  EXPECT_EQ(spot.direction, vec3(0, -1, 0));
  EXPECT_EQ(spot.inner_cone, 10);
  EXPECT_EQ(spot.outer_cone, 30);
  EXPECT_EQ(spot.tint, color(1));  // white unless said
  EXPECT_EQ(s.punctual_lights[2].kind, punctual_kind::directional);
  EXPECT_EQ(s.punctual_lights[2].direction, vec3(1, -2, 0.5));
  EXPECT_EQ(s.punctual_lights[2].angular_diameter, 0);
  EXPECT_EQ(s.punctual_lights[3].angular_diameter, 0.53);
  EXPECT_EQ(s.punctual_lights[3].intensity, 100000);
}

bool same(const punctual_light& a, const punctual_light& b) {
  return a.kind == b.kind && a.name == b.name && a.position == b.position &&
         a.direction == b.direction && a.tint == b.tint && a.intensity == b.intensity &&
         a.inner_cone == b.inner_cone && a.outer_cone == b.outer_cone &&
         a.angular_diameter == b.angular_diameter;
}

TEST(SceneFileLights, ADumpReloadsToTheSameLights) {
  const scene s = parse_scene_json(every_kind, "lights.json");
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("\"lights\""), std::string::npos) << dumped;
  EXPECT_NE(dumped.find("\"angular_diameter\": 0.53"), std::string::npos) << dumped;
  const scene back = parse_scene_json(dumped, "back.json");
  ASSERT_EQ(back.punctual_lights.size(), s.punctual_lights.size());
  for (std::size_t k = 0; k < s.punctual_lights.size(); ++k)
    EXPECT_TRUE(same(back.punctual_lights[k], s.punctual_lights[k])) << k;
  EXPECT_EQ(dump_scene_json(back), dumped);
  // A scene without lights dumps none.
  EXPECT_EQ(dump_scene_json(parse_scene_json("{" + sphere_part + "}", "x.json")).find("lights"),
            std::string::npos);
}

TEST(SceneFileLights, BadValuesNameTheFieldAndTheValue) {
  const struct {
    const char* light;
    const char* says;
  } bad[] = {
      {R"({"type":"point","position":[0,0,0],"intensity":-2})",
       "/lights/0/intensity: expected an intensity >= 0, got -2"},
      {R"({"type":"point","position":[0,1e999,0]})", "lights.json"},  // not finite: no JSON number
      {R"({"type":"point","position":[0,0,0],"color":[1,-1,0]})",
       "/lights/0/color/1: expected a color >= 0, got -1"},
      {R"({"type":"spot","position":[0,0,0],"direction":[0,0,0]})",
       "/lights/0/direction: expected a direction, got the zero vector [0.0,0.0,0.0]"},
      {R"({"type":"spot","position":[0,0,0],"direction":[0,-1,0],"inner_cone_angle":40,)"
       R"("outer_cone_angle":30})",
       "/lights/0/inner_cone_angle: expected at most outer_cone_angle (30), got 40"},
      {R"({"type":"spot","position":[0,0,0],"direction":[0,-1,0],"outer_cone_angle":95})",
       "/lights/0/outer_cone_angle: expected a number in [0, 90], got 95"},
      {R"({"type":"spot","position":[0,0,0],"direction":[0,-1,0],"inner_cone_angle":60})",
       "/lights/0/inner_cone_angle: expected at most outer_cone_angle (45), got 60"},
      {R"({"type":"directional","direction":[0,-1,0],"angular_diameter":180})",
       "/lights/0/angular_diameter: expected degrees in [0, 180), got 180"},
      {R"({"type":"directional","direction":[0,-1,0],"angular_diameter":-1})",
       "/lights/0/angular_diameter: expected degrees in [0, 180), got -1"},
      {R"({"type":"area","position":[0,0,0]})",
       "/lights/0/type: expected \"point\", \"spot\" or \"directional\", got \"area\""},
      {R"({"type":"point"})", "/lights/0: missing field \"position\""},
      {R"({"type":"point","position":[0,0,0],"direction":[0,-1,0]})",
       "/lights/0/direction: unknown field"},
      {R"({"type":"directional","direction":[0,-1,0],"intensity":"bright"})",
       "/lights/0/intensity: expected a number, got a string"},
  };
  for (const auto& b : bad) {
    std::string e = "no error";
    try {
      parse_scene_json(with_lights(b.light), "lights.json");
    } catch (const usage_error& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(b.says), std::string::npos) << b.light << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
}

TEST(SceneFileLights, TheCliExitsTwoNamingTheField) {
  test::temp_dir dir;
  const auto file = dir.path() / "bad.json";
  std::ofstream(file) << with_lights(R"({"type":"point","position":[0,2,0],"intensity":-5})");
  const auto out = dir.path() / "out.png";
  const test::process_result r = test::run_rtvk(
      {"render", "--scene", file.string(), "--backend", "cpu", "--output", out.string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/lights/0/intensity"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("got -5"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rtvk
