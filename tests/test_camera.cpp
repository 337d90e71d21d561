#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "camera.h"
#include "random.h"

namespace rtvk {
namespace {

void expect_vec(const vec3& got, double x, double y, double z) {
  EXPECT_DOUBLE_EQ(got.x, x);
  EXPECT_DOUBLE_EQ(got.y, y);
  EXPECT_DOUBLE_EQ(got.z, z);
}

TEST(Camera, DefaultIs400By225) {
  const camera cam;
  EXPECT_EQ(cam.image_width(), 400);
  EXPECT_EQ(cam.image_height(), 225);
  EXPECT_DOUBLE_EQ(cam.aspect_ratio(), 16.0 / 9.0);
}

TEST(Camera, DefaultVectorsAreTheLessons) {
  const camera cam;
  const double vw = 16.0 / 9.0 * 2.0;
  expect_vec(cam.origin(), 0, 0, 0);
  expect_vec(cam.horizontal(), vw, 0, 0);
  expect_vec(cam.vertical(), 0, 2, 0);
  expect_vec(cam.lower_left(), -vw / 2, -1, -1);
}

TEST(Camera, HeightIsAtLeastOne) {
  EXPECT_EQ(camera(16.0 / 9.0, 1).image_height(), 1);
  EXPECT_EQ(camera(1000.0, 10).image_height(), 1);
  EXPECT_EQ(camera(1.0, 1).image_height(), 1);
  EXPECT_EQ(camera(0.5, 3).image_height(), 6);
  EXPECT_EQ(camera(1e-3, 60).image_height(), 60000);
}

TEST(Camera, GetRayCornersAndCenter) {
  const camera cam;
  const double vw = 16.0 / 9.0 * 2.0;
  const ray lower_left = cam.get_ray(0, 0);
  expect_vec(lower_left.origin(), 0, 0, 0);
  expect_vec(lower_left.direction(), -vw / 2, -1, -1);
  expect_vec(cam.get_ray(1, 1).direction(), vw / 2, 1, -1);
  expect_vec(cam.get_ray(0.5, 0.5).direction(), 0, 0, -1);
}

TEST(Camera, InvalidArgumentsThrowNamingTheValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {0.0, -1.0, nan, inf, -inf}) {
    EXPECT_THROW(camera(bad, 400), std::invalid_argument) << bad;
  }
  EXPECT_THROW(camera(1.0, 0), std::invalid_argument);
  EXPECT_THROW(camera(1.0, -5), std::invalid_argument);
  EXPECT_THROW(camera(1.0, max_image_side + 1), std::invalid_argument);
  // A tiny aspect would make the height overflow an int.
  EXPECT_THROW(camera(1e-9, 400), std::invalid_argument);
  try {
    camera(-2.5, 400);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("-2.5"), std::string::npos) << e.what();
  }
  try {
    camera(1.0, 0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("got 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

TEST(PosedCamera, DefaultPoseIsExactlyTheLessonsCamera) {
  const camera lesson(16.0 / 9.0, 400);
  const camera posed(camera_pose{}, 16.0 / 9.0, 400);
  EXPECT_EQ(posed.origin(), lesson.origin());
  EXPECT_EQ(posed.horizontal(), lesson.horizontal());
  EXPECT_EQ(posed.vertical(), lesson.vertical());
  EXPECT_EQ(posed.lower_left(), lesson.lower_left());
  EXPECT_EQ(lesson.lens_radius(), 0.0);
  EXPECT_EQ(lesson.get_ray(0.3, 0.7).direction(), lesson.get_ray(0.3, 0.7, {0.5, 0.5}).direction());
}

TEST(PosedCamera, LookatIsAtTheImageCenter) {
  camera_pose p;
  p.lookfrom = point3(13, 2, 3);
  p.lookat = point3(0, 0, 0);
  p.vfov = 20;
  p.focus_dist = 7;
  const camera cam(p, 1.5, 300);
  const vec3 d = unit_vector(cam.get_ray(0.5, 0.5).direction());
  const vec3 want = unit_vector(p.lookat - p.lookfrom);
  EXPECT_NEAR(glm::length(d - want), 0.0, 1e-12);
  EXPECT_EQ(cam.origin(), p.lookfrom);
  // The image's up is vup's component perpendicular to the view: +y here.
  EXPECT_GT(glm::dot(cam.vertical(), vec3(0, 1, 0)), 0);
}

TEST(PosedCamera, VfovGivesTheViewport) {
  for (double vfov : {20.0, 60.0, 90.0, 120.0}) {
    camera_pose p;
    p.vfov = vfov;
    p.focus_dist = 2.5;
    const camera cam(p, 2.0, 100);
    const double h = 2 * std::tan(vfov * pi / 360) * 2.5;  // on the focus plane
    EXPECT_NEAR(glm::length(cam.vertical()), h, 1e-12) << vfov;
    EXPECT_NEAR(glm::length(cam.horizontal()), 2.0 * h, 1e-12) << vfov;
    // The top and bottom rows see vfov degrees apart.
    const vec3 top = cam.get_ray(0.5, 1).direction(), bottom = cam.get_ray(0.5, 0).direction();
    const double seen = std::acos(glm::dot(unit_vector(top), unit_vector(bottom))) * 180 / pi;
    EXPECT_NEAR(seen, vfov, 1e-9) << vfov;
  }
}

TEST(PosedCamera, LensSamplesMeetOnTheFocusPlane) {
  camera_pose p;
  p.lookfrom = point3(3, 3, 2);
  p.lookat = point3(0, 0, -1);
  p.aperture = 2.0;
  p.focus_dist = 4;
  const camera cam(p, 16.0 / 9.0, 200);
  EXPECT_DOUBLE_EQ(cam.lens_radius(), 1.0);
  const ray pin = cam.get_ray(0.2, 0.6);
  for (glm::dvec2 lens : {glm::dvec2(1, 0), glm::dvec2(0, -1), glm::dvec2(0.3, 0.4)}) {
    const ray r = cam.get_ray(0.2, 0.6, lens);
    // The origin moves across the lens...
    EXPECT_NEAR(glm::length(r.origin() - pin.origin()), glm::length(lens), 1e-12);
    // ...but every lens sample aims at the same point on the focus plane.
    EXPECT_NEAR(glm::length(r.at(1) - pin.at(1)), 0.0, 1e-12);
  }
}

TEST(PosedCamera, InvalidPosesThrow) {
  camera_pose p;
  for (double vfov : {0.0, 180.0, -5.0, std::nan("")}) {
    p = {};
    p.vfov = vfov;
    EXPECT_THROW(camera(p, 1.0, 10), std::invalid_argument) << vfov;
  }
  p = {};
  p.lookat = p.lookfrom;
  EXPECT_THROW(camera(p, 1.0, 10), std::invalid_argument);
  p = {};
  p.vup = vec3(0, 0, 1);  // parallel to the view direction
  EXPECT_THROW(camera(p, 1.0, 10), std::invalid_argument);
  p = {};
  p.aperture = -1;
  EXPECT_THROW(camera(p, 1.0, 10), std::invalid_argument);
  p = {};
  p.focus_dist = 0;
  EXPECT_THROW(camera(p, 1.0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace rtvk
