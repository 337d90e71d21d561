#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
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
  expect_vec(lower_left.origin, 0, 0, 0);
  expect_vec(lower_left.direction, -vw / 2, -1, -1);
  expect_vec(cam.get_ray(1, 1).direction, vw / 2, 1, -1);
  expect_vec(cam.get_ray(0.5, 0.5).direction, 0, 0, -1);
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

void expect_exact(const vec3& got, double x, double y, double z) {
  // 17 digits: a vector one rounding away from the answer must not print as the answer.
  std::ostringstream seen;
  seen << std::setprecision(17) << "got (" << got.x << ", " << got.y << ", " << got.z << ")";
  EXPECT_EQ(got.x, x) << seen.str();
  EXPECT_EQ(got.y, y) << seen.str();
  EXPECT_EQ(got.z, z) << seen.str();
}

// Exact, not nearly: the lesson's image depends on these bits (its viewport height is 2 because
// tan 45 degrees is taken as exactly 1).
TEST(PosedCamera, DefaultPoseGivesTheLessonsVectorsAndIgnoresTheLens) {
  // Aspect 2 keeps every number exact: viewport 2 high and 2 * 2 = 4 wide at focus distance 1;
  // w = (0, 0, 1), u = vup x w = (0, 1, 0) x (0, 0, 1) = (1, 0, 0), v = w x u = (0, 1, 0);
  // lower_left = origin - horizontal / 2 - vertical / 2 - w = (-2, -1, -1).
  const camera cam(camera_pose{}, 2.0, 100);
  EXPECT_EQ(cam.image_height(), 50);
  expect_exact(cam.origin(), 0, 0, 0);
  expect_exact(cam.horizontal(), 4, 0, 0);
  expect_exact(cam.vertical(), 0, 2, 0);
  expect_exact(cam.lower_left(), -2, -1, -1);
  expect_exact(cam.lens_u(), 1, 0, 0);
  expect_exact(cam.lens_v(), 0, 1, 0);
  EXPECT_EQ(cam.lens_radius(), 0.0);
  // A pinhole: the lens sample moves nothing. Direction = lower_left + 0.25 * horizontal +
  // 0.75 * vertical - origin = (-2 + 1, -1 + 1.5, -1) = (-1, 0.5, -1).
  const ray r = cam.get_ray(0.25, 0.75, {0.5, 0.5});
  expect_exact(r.origin, 0, 0, 0);
  expect_exact(r.direction, -1, 0.5, -1);
}

TEST(PosedCamera, LookingDownMinusXFromAnOffsetPoint) {
  // From (1, 2, 3) toward (0, 2, 3), vfov 90 (tan 45 = 1), aspect 2, focus distance 1:
  //   w = unit(lookfrom - lookat) = (1, 0, 0)
  //   u = unit(vup x w) = (0, 1, 0) x (1, 0, 0) = (1*0 - 0*0, 0*1 - 0*0, 0*0 - 1*1) = (0, 0, -1)
  //   v = w x u = (1, 0, 0) x (0, 0, -1) = (0*-1 - 0*0, 0*0 - 1*-1, 1*0 - 0*0) = (0, 1, 0)
  //   horizontal = 1 * (2 * 2) * u = (0, 0, -4); vertical = 1 * 2 * v = (0, 2, 0)
  //   lower_left = (1, 2, 3) - (0, 0, -2) - (0, 1, 0) - (1, 0, 0) = (0, 1, 5)
  // Facing -x with +y up, the right hand points to -z: the image's left edge is at z = 5.
  camera_pose p;
  p.lookfrom = point3(1, 2, 3);
  p.lookat = point3(0, 2, 3);
  const camera cam(p, 2.0, 64);
  expect_exact(cam.origin(), 1, 2, 3);
  expect_exact(cam.horizontal(), 0, 0, -4);
  expect_exact(cam.vertical(), 0, 2, 0);
  expect_exact(cam.lower_left(), 0, 1, 5);
  expect_exact(cam.lens_u(), 0, 0, -1);
  expect_exact(cam.lens_v(), 0, 1, 0);
  // (s, t) = (0.25, 0.75): (0, 1, 5) + (0, 0, -1) + (0, 1.5, 0) - (1, 2, 3) = (-1, 0.5, 1).
  const ray r = cam.get_ray(0.25, 0.75);
  expect_exact(r.origin, 1, 2, 3);
  expect_exact(r.direction, -1, 0.5, 1);
  // The center looks straight at lookat, one focus distance away.
  expect_exact(ray_at(cam.get_ray(0.5, 0.5), 1), 0, 2, 3);
}

TEST(PosedCamera, ThinLensRaysLeaveTheLensAndMeetOnTheFocusPlane) {
  // From (0, 0, 4) toward the origin, vfov 90, aspect 1.5, aperture 1 (radius 0.5), focus
  // distance 4: w = (0, 0, 4) / 4 = (0, 0, 1), u = (1, 0, 0), v = (0, 1, 0);
  //   horizontal = 4 * (1.5 * 2) * u = (12, 0, 0); vertical = 4 * 2 * v = (0, 8, 0)
  //   lower_left = (0, 0, 4) - (6, 0, 0) - (0, 4, 0) - 4 * (0, 0, 1) = (-6, -4, 0)
  camera_pose p;
  p.lookfrom = point3(0, 0, 4);
  p.lookat = point3(0, 0, 0);
  p.aperture = 1;
  p.focus_dist = 4;
  const camera cam(p, 1.5, 90);
  EXPECT_EQ(cam.lens_radius(), 0.5);
  expect_exact(cam.horizontal(), 12, 0, 0);
  expect_exact(cam.vertical(), 0, 8, 0);
  expect_exact(cam.lower_left(), -6, -4, 0);

  // Center, lens (1, 0): offset = 0.5 * 1 * u = (0.5, 0, 0), so the ray leaves (0.5, 0, 4) with
  // direction (-6, -4, 0) + (6, 0, 0) + (0, 4, 0) - (0, 0, 4) - (0.5, 0, 0) = (-0.5, 0, -4).
  const ray center = cam.get_ray(0.5, 0.5, {1, 0});
  expect_exact(center.origin, 0.5, 0, 4);
  expect_exact(center.direction, -0.5, 0, -4);
  expect_exact(ray_at(center, 1), 0, 0, 0);  // lookat, in focus

  // Lower-right corner (1, 0), lens (0, -1): offset = 0.5 * -1 * v = (0, -0.5, 0), origin
  // (0, -0.5, 4), direction (-6, -4, 0) + (12, 0, 0) - (0, 0, 4) - (0, -0.5, 0) = (6, -3.5, -4).
  const ray corner = cam.get_ray(1, 0, {0, -1});
  expect_exact(corner.origin, 0, -0.5, 4);
  expect_exact(corner.direction, 6, -3.5, -4);
  expect_exact(ray_at(corner, 1), 6, -4, 0);  // the focus plane's lower-right corner
}

TEST(PosedCamera, VfovSixtyAtFocusThreeGivesAViewportTwoRootThreeHigh) {
  // tan 30 degrees = 1 / sqrt 3, so at focus distance 3 the viewport is 2 * 3 / sqrt 3 =
  // 2 sqrt 3 = 3.464101615137755 high and, at aspect 1.5, 3 sqrt 3 = 5.196152422706632 wide.
  camera_pose p;
  p.vfov = 60;
  p.focus_dist = 3;
  const camera cam(p, 1.5, 60);
  EXPECT_NEAR(cam.vertical().y, 3.464101615137755, 4e-15);
  EXPECT_NEAR(cam.horizontal().x, 5.196152422706632, 4e-15);
  EXPECT_NEAR(cam.lower_left().x, -2.598076211353316, 4e-15);
  EXPECT_NEAR(cam.lower_left().y, -1.7320508075688774, 4e-15);
  EXPECT_EQ(cam.lower_left().z, -3);
}

TEST(PosedCamera, LookatIsAtTheImageCenter) {
  camera_pose p;
  p.lookfrom = point3(13, 2, 3);
  p.lookat = point3(0, 0, 0);
  p.vfov = 20;
  p.focus_dist = 7;
  const camera cam(p, 1.5, 300);
  const vec3 d = unit_vector(cam.get_ray(0.5, 0.5).direction);
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
    const vec3 top = cam.get_ray(0.5, 1).direction, bottom = cam.get_ray(0.5, 0).direction;
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
    EXPECT_NEAR(glm::length(r.origin - pin.origin), glm::length(lens), 1e-12);
    // ...but every lens sample aims at the same point on the focus plane.
    EXPECT_NEAR(glm::length(ray_at(r, 1) - ray_at(pin, 1)), 0.0, 1e-12);
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
