#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "camera.h"

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
