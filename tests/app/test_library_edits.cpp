// The library's edits between renders (rtvk.h): objects placed by Scene::place draw as the scene
// file that puts them there draws (the file's own transform path, read by the scene reader, is
// the oracle), a renderer sets the scene up once and again only after an edit, and a camera
// from an OpenCV calibration file is the camera of the same numbers.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "object_placement.h"
#include "rtvk.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

// A ground, a red ball, a gold box, a triangle and an instance of a group: ids 1 to 5. (dx, dz)
// moves the red ball, the box, the triangle and the instance, as the file writes them.
std::string scene_json(double dx = 0, double dz = 0) {
  const auto at = [&](double x, double y, double z) {
    return "[" + std::to_string(x + dx) + ", " + std::to_string(y) + ", " + std::to_string(z + dz) +
           "]";
  };
  return R"({"camera": {"lookfrom": [0, 1, 6], "lookat": [0, 0.5, 0], "vfov": 40},
    "render": {"width": 32, "aspect": "4:3", "spp": 2, "max_depth": 4},
    "materials": {"red": {"type": "lambertian", "albedo": [0.8, 0.2, 0.2]},
                  "gray": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]},
                  "gold": {"type": "metal", "albedo": [0.8, 0.6, 0.2], "fuzz": 0.1}},
    "spheres": [{"center": [0, -100, 0], "radius": 100, "material": "gray"},
                {"center": )" +
         at(-1, 0.5, 0) + R"(, "radius": 0.5, "material": "red"}],
    "boxes": [{"a": )" +
         at(0.5, 0, -0.5) + R"(, "b": )" + at(1.5, 1, 0.5) + R"(, "material": "gold"}],
    "triangles": [{"vertices": [)" +
         at(-2, 0, -1) + ", " + at(-1, 0, -1) + ", " + at(-1.5, 1, -1) +
         R"(], "material": "red"}],
    "groups": {"g": {"spheres": [{"center": [0, 0.25, 0], "radius": 0.25, "material": "gold"}]}},
    "instances": [{"group": "g", "transform": {"translate": )" +
         at(0, 0, 1) + R"(}}]})";
}

std::vector<double> translation(double x, double y, double z) {
  return {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z, 0, 0, 0, 1};
}

const std::vector<double> identity = translation(0, 0, 0);

class LibraryEdits : public testing::TestWithParam<const char*> {};  // the CPU's precision

TEST_P(LibraryEdits, PlacedObjectsDrawAsTheFileThatPutsThemThere) {
  api::Scene scene = api::Scene::from_json(scene_json());
  api::Renderer renderer(scene, "cpu", "", GetParam());
  const api::Camera cam = api::Camera::from_scene(scene);
  const std::vector<float> before = renderer.render(cam).rgb;
  for (std::uint32_t id : {2u, 3u, 4u, 5u}) scene.place(id, translation(0.25, 0, 0.5));
  const std::vector<float> moved = renderer.render(cam).rgb;
  const api::Scene file = api::Scene::from_json(scene_json(0.25, 0.5));
  const std::vector<float> expected = api::Renderer(file, "cpu", "", GetParam()).render(cam).rgb;
  EXPECT_NE(moved, before);
  EXPECT_EQ(moved, expected);
  // Placements replace each other: a second one is from the scene's placement, not the last.
  for (std::uint32_t id : {2u, 3u, 4u, 5u}) scene.place(id, translation(0.125, 0, 0.25));
  for (std::uint32_t id : {2u, 3u, 4u, 5u}) scene.place(id, translation(0.25, 0, 0.5));
  EXPECT_EQ(renderer.render(cam).rgb, expected);
  for (std::uint32_t id : {2u, 3u, 4u, 5u}) scene.place(id, identity);
  EXPECT_EQ(renderer.render(cam).rgb, before);
}

TEST_P(LibraryEdits, ARendererSetsTheSceneUpOnceAndAgainAfterAnEdit) {
  api::Scene scene = api::Scene::from_json(scene_json());
  api::Renderer renderer(scene, "cpu", "", GetParam());
  const api::Camera cam = api::Camera::from_scene(scene);
  EXPECT_EQ(renderer.set_ups(), 0u);
  const std::vector<float> first = renderer.render(cam).rgb;
  EXPECT_EQ(renderer.render(cam).rgb, first);  // the kept world draws the same image
  EXPECT_EQ(renderer.set_ups(), 1u);
  scene.set_material("red", R"({"type": "lambertian", "albedo": [0.2, 0.2, 0.8]})");
  EXPECT_NE(renderer.render(cam).rgb, first);
  EXPECT_EQ(renderer.set_ups(), 2u);
}

INSTANTIATE_TEST_SUITE_P(Precisions, LibraryEdits, testing::Values("reference", "fast"));

TEST(LibraryObjects, AreListedInTheObjectIdAovsOrder) {
  const api::Scene scene = api::Scene::from_json(scene_json());
  const std::vector<api::Scene::Object> objects = scene.objects();
  ASSERT_EQ(objects.size(), 5u);
  const char* kinds[] = {"sphere", "sphere", "box", "triangle", "instance"};
  const char* materials[] = {"gray", "red", "gold", "red", ""};
  const std::size_t primitives[] = {1, 1, 6, 1, 1};
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(objects[k].id, k + 1);
    EXPECT_EQ(objects[k].kind, kinds[k]);
    EXPECT_EQ(objects[k].material, materials[k]);
    EXPECT_EQ(objects[k].primitives, primitives[k]);
  }
  EXPECT_EQ(objects[4].group, "g");
  // Their boxes, where they are now: the box's corners, the instance's sphere placed.
  using box = std::array<double, 3>;
  EXPECT_EQ(objects[2].lo, (box{0.5, 0, -0.5}));
  EXPECT_EQ(objects[2].hi, (box{1.5, 1, 0.5}));
  EXPECT_EQ(objects[4].lo, (box{-0.25, 0, 0.75}));
  EXPECT_EQ(objects[4].hi, (box{0.25, 0.5, 1.25}));
  api::Scene moved = api::Scene::from_json(scene_json());
  moved.place(3, translation(1, 2, 4));
  EXPECT_EQ(moved.objects()[2].lo, (box{1.5, 2, 3.5}));
  // The AOV sees the ball (id 2) where the ball is.
  api::Renderer r(scene, "cpu");
  const api::Camera cam = api::Camera::look_at({-1, 0.5, 4}, {-1, 0.5, 0}, 8, 8, 10);
  api::RenderOptions o;
  o.aovs = api::aov_object_id;
  EXPECT_EQ(r.render(cam, o).object_id[4 * 8 + 4], 2u);
}

TEST(LibraryObjects, BadPlacementsAreBadInputNamingTheObject) {
  api::Scene scene = api::Scene::from_json(scene_json());
  const auto message = [&](std::uint32_t id, const std::vector<double>& m) -> std::string {
    try {
      scene.place(id, m);
    } catch (const api::bad_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message(9, identity), "object 9: the scene has objects 1 to 5");
  EXPECT_EQ(message(0, identity), "object 0: the scene has objects 1 to 5");
  const std::vector<double> stretch = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(message(2, stretch),
            "object 2: a sphere can be turned, moved and scaled evenly, not stretched");
  EXPECT_EQ(message(5, stretch), "no exception");  // an instance may be stretched
  EXPECT_EQ(message(3, {1, 2, 3}), "matrix: expected 12 or 16 numbers (row-major), got 3");
  std::vector<double> flat = identity;
  flat[0] = 0;
  EXPECT_EQ(message(3, flat).rfind("matrix: the transform cannot place anything", 0), 0u);
}

// Tangents are directions in the surface: a turn carries them, a mirror also flips their
// handedness and swaps the last two vertices' (as the mesh reader places a file's).
TEST(LibraryObjects, PlacingAMeshCarriesItsTangents) {
  rtvk::scene s;
  s.materials = {{"m", {}}};
  triangle tri;
  tri.p = {point3(0, 0, 0), point3(1, 0, 0), point3(0, 1, 0)};
  tri.shading = 0;
  triangle_shading sh;
  sh.normal = {vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, 1)};
  sh.tangent = {glm::vec4(1, 0, 0, 1), glm::vec4(0, 1, 0, 1), glm::vec4(0.6f, 0.8f, 0, -1)};
  sh.has_tangent = true;
  s.triangles = {tri};
  s.shading = {sh};
  const object_original o = *find_object(s, 1);
  ASSERT_FALSE(place_object(s, o, make_transform(vec3(1), vec3(0, 0, 1), 90, vec3(0))));
  const auto near = [](glm::vec4 a, glm::vec4 b) {
    return glm::all(glm::lessThan(glm::abs(a - b), glm::vec4(1e-6f)));
  };
  EXPECT_TRUE(near(s.shading[0].tangent[0], glm::vec4(0, 1, 0, 1)));
  EXPECT_TRUE(near(s.shading[0].tangent[1], glm::vec4(-1, 0, 0, 1)));
  EXPECT_TRUE(near(s.shading[0].tangent[2], glm::vec4(-0.8f, 0.6f, 0, -1)));
  transform mirror;
  mirror.linear[0][0] = -1;  // x -> -x
  ASSERT_FALSE(place_object(s, o, mirror));
  EXPECT_TRUE(near(s.shading[0].tangent[0], glm::vec4(-1, 0, 0, -1)));
  EXPECT_TRUE(near(s.shading[0].tangent[1], glm::vec4(-0.6f, 0.8f, 0, 1)));  // vertex 2's
  EXPECT_TRUE(near(s.shading[0].tangent[2], glm::vec4(0, 1, 0, -1)));        // vertex 1's
}

// An edit the scene reader would refuse leaves the scene as it was.
TEST(LibraryObjects, EditsAreCheckedAsTheSceneFileWouldBe) {
  api::Scene scene = api::Scene::from_json(scene_json());
  const std::string before = scene.to_json();
  try {
    scene.place(2, translation(1e19, 0, 0));
    FAIL() << "no exception";
  } catch (const api::bad_input& e) {
    EXPECT_EQ(std::string(e.what()).rfind("object 2: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(scene.to_json(), before);
  scene.place(2, translation(1, 0, 0));
  const std::string moved = scene.to_json();
  EXPECT_THROW(scene.place(2, translation(-1e19, 0, 0)), api::bad_input);
  EXPECT_EQ(scene.to_json(), moved);  // back where the last place put it
}

TEST(LibraryCameras, AnOpenCvCalibrationFileIsTheCameraOfItsNumbers) {
  test::temp_dir dir;
  const std::string file = (dir.path() / "cam.yaml").string();
  std::ofstream(file) << "%YAML:1.0\n---\nimage_width: 40\nimage_height: 30\n"
                         "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
                         "   data: [ 36., 0., 19.5, 0., 35., 14.5, 0., 0., 1. ]\n"
                         "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n"
                         "   dt: d\n   data: [ -0.2, 0.05, 0.001, -0.002, 0. ]\n";
  // A camera 6 units back on +z looking at the origin (OpenCV: +z forward, +y down).
  const std::array<double, 16> w2c = {-1, 0, 0, 0, 0, -1, 0, 0.5, 0, 0, -1, 6, 0, 0, 0, 1};
  const api::Camera from_file = api::Camera::from_opencv_file(w2c, file);
  const api::Camera from_numbers =
      api::Camera::from_opencv(w2c, 36, 35, 19.5, 14.5, 40, 30, {-0.2, 0.05, 0.001, -0.002, 0});
  EXPECT_EQ(from_file.width(), 40);
  EXPECT_EQ(from_file.height(), 30);
  const api::Scene scene = api::Scene::from_json(scene_json());
  api::Renderer r(scene, "cpu");
  EXPECT_EQ(r.render(from_file).rgb, r.render(from_numbers).rgb);
  EXPECT_THROW(api::Camera::from_opencv_file(w2c, (dir.path() / "none.yaml").string()),
               api::bad_input);
}

}  // namespace
}  // namespace rtvk
