// glTF's KHR_lights_punctual read into the scene's punctual lights (gltf_lights.cpp): each light
// placed by its node's world transform and the loader's placement, shining down the node's -Z,
// its cones converted to degrees, bad lights refused naming the node and the light; and the
// Khronos LightsPunctualLamp's five point lights where they stand in the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>

#include <nlohmann/json.hpp>

#include "errors.h"
#include "mesh_file.h"
#include "mesh_helpers.h"

namespace rtvk {
namespace {

using nlohmann::json;

// A cube's triangles (node 0) and three lights: a spot under a parent that moves it to (1, 2, 3)
// and turns it 90 degrees about x (its child sits at local (0, 0, 1)), a point at (5, 0, 0) and a
// directional light without a transform.
json lit_gltf() {
  json doc = json::parse(test::gltf_json(test::cube_sphere(1, 1.0)));
  const double h = std::sqrt(0.5);
  doc["scenes"][0]["nodes"] = {0, 1, 3, 4};
  doc["nodes"].push_back(
      {{"translation", {1, 2, 3}}, {"rotation", {h, 0, 0, h}}, {"children", {2}}});
  doc["nodes"].push_back(
      {{"translation", {0, 0, 1}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  doc["nodes"].push_back({{"name", "bulb"},
                          {"translation", {5, 0, 0}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
  doc["extensionsUsed"] = {"KHR_lights_punctual"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"},
       {"name", "lamp"},
       {"color", {1, 0.5, 0.25}},
       {"intensity", 40},
       {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}},
      {{"type", "point"}, {"intensity", 3}, {"range", 10}},
      {{"type", "directional"}, {"intensity", 2.5}}};
  return doc;
}

scene load(const json& doc, const transform& placement = {}) {
  scene s;
  mesh_placement how;
  how.placement = placement;
  load_mesh_bytes(s, doc.dump(), "gltf", "lit.gltf", "", how);
  return s;
}

void expect_near(const vec3& a, const vec3& b, double tolerance = 1e-12) {
  EXPECT_NEAR(glm::length(a - b), 0, tolerance) << a.x << " " << a.y << " " << a.z;
}

TEST(GltfLights, NodesPlaceTheirLightsAndTheyShineDownMinusZ) {
  const scene s = load(lit_gltf());
  ASSERT_EQ(s.punctual_lights.size(), 3u);
  const punctual_light& spot = s.punctual_lights[0];
  EXPECT_EQ(spot.kind, punctual_kind::spot);
  EXPECT_EQ(spot.name, "lamp");
  expect_near(spot.position, {1, 1, 3});   // (1, 2, 3) + the turn of (0, 0, 1)
  expect_near(spot.direction, {0, 1, 0});  // the turn of -Z
  EXPECT_EQ(spot.tint, color(1, 0.5, 0.25));
  EXPECT_EQ(spot.intensity, 40);
  EXPECT_NEAR(spot.inner_cone, 0.25 * 180 / std::numbers::pi, 1e-12);
  EXPECT_NEAR(spot.outer_cone, 0.5 * 180 / std::numbers::pi, 1e-12);
  const punctual_light& point = s.punctual_lights[1];
  EXPECT_EQ(point.kind, punctual_kind::point);
  EXPECT_EQ(point.name, "bulb");  // the node's, the light having none
  EXPECT_EQ(point.position, point3(5, 0, 0));
  EXPECT_EQ(point.tint, color(1));  // glTF's default white
  const punctual_light& sun = s.punctual_lights[2];
  EXPECT_EQ(sun.kind, punctual_kind::directional);
  EXPECT_EQ(sun.direction, vec3(0, 0, -1));
  EXPECT_EQ(sun.intensity, 2.5);
  EXPECT_EQ(sun.angular_diameter, 0);
}

TEST(GltfLights, TheLoadersPlacementMovesAndTurnsThem) {
  transform t;
  t.linear = glm::dmat3(0, 0, -2, 0, 2, 0, 2, 0, 0);  // scale 2, turned 90 degrees about y
  t.offset = {10, 0, 0};
  const scene s = load(lit_gltf(), t);
  ASSERT_EQ(s.punctual_lights.size(), 3u);
  expect_near(s.punctual_lights[0].position, t.apply_point({1, 1, 3}));
  expect_near(s.punctual_lights[0].direction, {0, 1, 0});
  expect_near(s.punctual_lights[1].position, {10, 0, -10});
  expect_near(s.punctual_lights[2].direction, {-1, 0, 0});  // -Z turned about y, unit
}

TEST(GltfLights, BadLightsAreRefusedNamingTheNodeAndTheLight) {
  const struct {
    const char* pointer;
    json value;
    const char* says;
  } bad[] = {
      {"/extensions/KHR_lights_punctual/lights/1/intensity", -1,
       "lit.gltf: node 3 KHR_lights_punctual: light 1: intensity -1 is not a finite number >= 0"},
      {"/extensions/KHR_lights_punctual/lights/0/spot/innerConeAngle", 0.75,
       "light 0: spot cones 0.75 and 0.5 are not 0 <= inner < outer <= pi / 2"},
      {"/extensions/KHR_lights_punctual/lights/0/spot/outerConeAngle", 2,
       "light 0: spot cones 0.25 and 2 are not"},
      {"/extensions/KHR_lights_punctual/lights/2/type", "area",
       "light 2: type \"area\" is not point, spot or directional"},
      {"/extensions/KHR_lights_punctual/lights/1/color",
       {1, 2, 0},
       "light 1: color 2 is not in [0, 1]"},
      {"/nodes/3/extensions/KHR_lights_punctual/light", 7,
       "node 3 KHR_lights_punctual: light 7 does not exist"},
      {"/nodes/4/scale", {0, 0, 0}, "node 4 KHR_lights_punctual: its node's transform cannot"},
  };
  for (const auto& b : bad) {
    json doc = lit_gltf();
    doc[json::json_pointer(b.pointer)] = b.value;
    std::string e = "no error";
    try {
      load(doc);
    } catch (const usage_error& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(b.says), std::string::npos) << b.pointer << ": " << e;
  }
}

// The Khronos LightsPunctualLamp's five point lights, on root nodes 3 to 7, each at its matrix's
// translation, turned so that -Z is -Y; with the file's intensities (candela) and colors; and
// placed as a scene file's mesh is.
void expect_lamp_lights(const std::filesystem::path& file) {
  SCOPED_TRACE(file.string());
  scene s;
  load_mesh(s, file, {});
  ASSERT_EQ(s.punctual_lights.size(), 5u);
  const struct {
    const char* name;
    double intensity;
    point3 at;
  } want[] = {
      {"Point", 15, {0.04622355476021767, 0.9077973365783693, 0.006696629337966442}},
      {"Point.002", 1.5, {0.1754562258720398, -0.7642198801040649, -0.005704082548618317}},
      {"Point.003", 80, {0.13761821389198303, 2.066983699798584, -1.178986430168152}},
      {"Point.001", 80, {0.0442890003323555, 0.25436437129974365, -1.209032416343689}},
      {"Point.004", 180, {0.2920210361480713, 1.0323998928070068, 1.5589159727096558}},
  };
  for (std::size_t k = 0; k < 5; ++k) {
    const punctual_light& l = s.punctual_lights[k];
    EXPECT_EQ(l.kind, punctual_kind::point) << k;
    EXPECT_EQ(l.name, want[k].name);
    EXPECT_EQ(l.intensity, want[k].intensity);
    expect_near(l.position, want[k].at, 1e-15);
    expect_near(l.direction, {0, -1, 0}, 1e-7);
  }
  EXPECT_EQ(s.punctual_lights[0].tint, color(1, 0.6318749785423279, 0.23909975588321689));
  EXPECT_EQ(s.punctual_lights[1].tint, color(1));
  // Placed as a scene file's mesh is: 2x and moved up 1.
  transform t;
  t.linear = glm::dmat3(2.0);
  t.offset = {0, 1, 0};
  scene placed;
  load_mesh(placed, file, {-1, t, false});
  ASSERT_EQ(placed.punctual_lights.size(), 5u);
  expect_near(placed.punctual_lights[4].position, 2.0 * want[4].at + vec3(0, 1, 0), 1e-14);
}

// Its lights and their nodes, shipped (tests/data/gltf/LightsPunctualLamp: the meshes left out).
TEST(GltfLights, LightsPunctualLampsLightsAreWhereTheFilePutsThem) {
  expect_lamp_lights(RTVK_TEST_DATA "/gltf/LightsPunctualLamp/LightsPunctualLampLights.gltf");
}

}  // namespace
}  // namespace rtvk
