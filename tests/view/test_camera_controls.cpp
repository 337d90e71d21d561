// The viewer's camera moves, without a window: each keeps what it should (the look-at distance,
// the view direction) and moves by exactly the documented amount.
#include <gtest/gtest.h>

#include <cmath>

#include "camera_controls.h"

namespace rtvk {
namespace {

constexpr double degrees = 3.14159265358979323846 / 180;

camera_pose book_final_pose() {
  camera_pose p;
  p.lookfrom = point3(13, 2, 3);
  p.lookat = point3(0, 0, 0);
  p.vup = vec3(0, 1, 0);
  p.vfov = 20;
  p.aperture = 0.1;
  p.focus_dist = 10;
  return p;
}

double angle_to_up(const camera_pose& p) {
  return std::acos(glm::dot(glm::normalize(p.lookfrom - p.lookat), glm::normalize(p.vup)));
}

TEST(CameraControls, OrbitTurnsAboutTheTargetByTheRateAndKeepsTheDistance) {
  const camera_pose p = book_final_pose();
  const camera_pose yawed = view::orbit(p, 40, 0);  // 10 degrees about +y
  EXPECT_NEAR(glm::length(yawed.lookfrom - p.lookat), glm::length(p.lookfrom - p.lookat), 1e-12);
  EXPECT_NEAR(yawed.lookfrom.y, 2, 1e-12);
  const double turned = std::atan2(-yawed.lookfrom.z, yawed.lookfrom.x) - std::atan2(-3.0, 13.0);
  EXPECT_NEAR(turned, 10 * degrees, 1e-12);
  const camera_pose raised = view::orbit(p, 0, 20);  // 5 degrees towards vup
  EXPECT_NEAR(angle_to_up(p) - angle_to_up(raised), 5 * degrees, 1e-12);
  EXPECT_EQ(raised.lookat, p.lookat);
  // Never over the pole.
  EXPECT_NEAR(angle_to_up(view::orbit(p, 0, 10000)), 1 * degrees, 1e-9);
  EXPECT_NEAR(angle_to_up(view::orbit(p, 0, -10000)), 179 * degrees, 1e-9);
}

TEST(CameraControls, PanMovesEyeAndTargetTogetherByTheViewsScale) {
  const camera_pose p = book_final_pose();
  const camera_pose moved = view::pan(p, 100, 0, 400);
  const vec3 shift = moved.lookat - p.lookat;
  EXPECT_LT(glm::length((moved.lookfrom - p.lookfrom) - shift), 1e-12);
  // 100 of 400 pixels at the look-at distance, against the cursor: the scene follows it.
  const double distance = glm::length(p.lookfrom - p.lookat);
  EXPECT_NEAR(glm::length(shift), 100.0 / 400 * 2 * distance * std::tan(10 * degrees), 1e-12);
  EXPECT_NEAR(glm::dot(shift, glm::normalize(p.lookfrom - p.lookat)), 0, 1e-12);
  // The scene follows the cursor: a drag to the right moves the camera to its left (the look-at
  // point is then right of the centre by the drag), a drag up moves it down.
  const vec3 w = glm::normalize(p.lookfrom - p.lookat);
  const vec3 right = glm::normalize(glm::cross(p.vup, w)), up = glm::cross(w, right);
  EXPECT_NEAR(glm::dot(shift, right), -glm::length(shift), 1e-12);
  const vec3 shift_up = view::pan(p, 0, 100, 400).lookat - p.lookat;
  EXPECT_NEAR(glm::dot(shift_up, up), -glm::length(shift), 1e-12);
}

TEST(CameraControls, DollyFlyZoomStopAndProjectionSteps) {
  const camera_pose p = book_final_pose();
  const double d = glm::length(p.lookfrom - p.lookat);
  EXPECT_NEAR(glm::length(view::dolly(p, 2).lookfrom - p.lookat), d * 0.81, 1e-12);
  EXPECT_NEAR(glm::length(view::dolly(p, -1).lookfrom - p.lookat), d / 0.9, 1e-12);
  const camera_pose flown = view::fly(p, 1, 0, 0);
  EXPECT_NEAR(glm::length(flown.lookfrom - p.lookfrom), 0.05 * d, 1e-12);
  EXPECT_LT(glm::length((flown.lookat - p.lookat) - (flown.lookfrom - p.lookfrom)), 1e-12);
  EXPECT_LT(glm::length(flown.lookfrom), glm::length(p.lookfrom));  // forward: towards the scene
  EXPECT_NEAR(view::fly(p, 0, 0, 1).lookfrom.y, 2 + 0.05 * d, 1e-12);
  EXPECT_EQ(view::zoom(p, 1).vfov, 15);
  EXPECT_EQ(view::zoom(p, 100).vfov, 1);
  EXPECT_EQ(view::zoom(p, -100).vfov, 179);
  camera_pose pinhole = p;
  pinhole.aperture = 0;
  EXPECT_EQ(view::stop(pinhole, 1).aperture, 0.01);
  EXPECT_EQ(view::stop(view::stop(pinhole, 1), -1).aperture, 0);
  EXPECT_NEAR(view::stop(p, 2).aperture, 0.1 * 1.25 * 1.25, 1e-15);
  camera_pose cycled = p;
  for (int i = 0; i < 6; ++i) {
    cycled = view::next_projection(cycled);
    const bool lensless = cycled.projection != projection::perspective &&
                          cycled.projection != projection::orthographic;
    EXPECT_TRUE(!lensless || cycled.aperture == 0) << "a lens-less model gets no aperture";
  }
  EXPECT_EQ(cycled.projection, projection::perspective);  // six models, then round again
  EXPECT_EQ(view::next_projection(p).projection, projection::orthographic);
}

}  // namespace
}  // namespace rtvk
