// Camera paths: orbits against a hand-worked rotation, keyframes held and blended, and the
// orientation blend that must not flip where the view passes the up vector.
#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"
#include "camera_path.h"

namespace rtvk {
namespace {

void expect_near(const vec3& a, const vec3& b, double eps = 1e-12) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

camera_pose book_pose() {
  camera_pose p;
  p.lookfrom = point3(13, 2, 3);
  p.lookat = point3(0, 0, 0);
  p.vfov = 20;
  p.aperture = 0.1;
  p.focus_dist = 10;
  return p;
}

TEST(CameraPath, OrbitTurnsAboutTheUpAxisThroughTheLookAtPoint) {
  const camera_path orbit{camera_motion::orbit, book_pose(), 8, {}};
  EXPECT_EQ(orbit.at(0).lookfrom, book_pose().lookfrom);  // exactly, not nearly
  EXPECT_EQ(orbit.at(8).lookfrom, book_pose().lookfrom);
  EXPECT_EQ(orbit.at(-16).lookfrom, book_pose().lookfrom);
  // A quarter turn counter-clockwise seen from +y takes (x, z) = (13, 3) to (3, -13).
  expect_near(orbit.at(2).lookfrom, point3(3, 2, -13));
  expect_near(orbit.at(4).lookfrom, point3(-13, 2, -3));
  expect_near(orbit.at(10).lookfrom, point3(3, 2, -13));
  for (double t = 0; t < 8; t += 0.37) {
    const camera_pose p = orbit.at(t);
    EXPECT_NEAR(glm::length(p.lookfrom - p.lookat), glm::length(book_pose().lookfrom), 1e-12);
    EXPECT_EQ(p.lookat, book_pose().lookat);
    EXPECT_EQ(p.vfov, 20);
  }
}

TEST(CameraPath, OrbitAboutATiltedUpVector) {
  camera_pose p;
  p.lookfrom = point3(1, 0, 0);
  p.lookat = point3(0, 0, 0);
  p.vup = vec3(0, 0, 2);  // not unit length: only its direction counts
  const camera_path orbit{camera_motion::orbit, p, 4, {}};
  expect_near(orbit.at(1).lookfrom, point3(0, 1, 0));  // +x to +y about +z
}

camera_keyframe key(double time, point3 from, point3 at, double vfov) {
  camera_keyframe k;
  k.time = time;
  k.pose.lookfrom = from;
  k.pose.lookat = at;
  k.pose.vfov = vfov;
  return k;
}

TEST(CameraPath, KeyframesAreHeldAndBlended) {
  const camera_path path{
      camera_motion::keyframes,
      {},
      0,
      {key(1, point3(0, 0, 4), point3(0, 0, 0), 30), key(3, point3(4, 0, 4), point3(4, 0, 0), 50)}};
  EXPECT_EQ(path.at(-5).lookfrom, point3(0, 0, 4));  // before the first: held
  EXPECT_EQ(path.at(1).lookfrom, point3(0, 0, 4));   // at a keyframe: exactly its pose
  EXPECT_EQ(path.at(3).lookat, point3(4, 0, 0));
  EXPECT_EQ(path.at(99).lookfrom, point3(4, 0, 4));  // after the last: held
  const camera_pose mid = path.at(2);
  expect_near(mid.lookfrom, point3(2, 0, 4));  // linear position
  expect_near(mid.lookat, point3(2, 0, 0));    // same orientation at both ends: kept
  EXPECT_NEAR(mid.vfov, 40, 1e-12);
  expect_near(path.at(1.5).lookfrom, point3(1, 0, 4));
}

// The camera stays above the origin and swings from looking down-left to looking down-right,
// passing under the keyframes' up vector. Blending look-at points would build
// a camera whose up vector is parallel to the view halfway (no image at all) and whose right
// vector flips sign across it. The rotation blend keeps every frame valid and turns smoothly.
TEST(CameraPath, OrientationNeverFlipsPassingUnderTheUpVector) {
  const camera_path path{camera_motion::keyframes,
                         {},
                         0,
                         {key(0, point3(0, 5, 0), point3(-1, 0, 0), 40),
                          key(1, point3(0, 5, 0), point3(1, 0, 0), 40)}};
  check_camera_path(path);
  vec3 previous_right(0), previous_view(0);
  for (int k = 0; k <= 100; ++k) {
    const camera_pose p = path.at(k / 100.0);
    const camera cam(p, 1, 8);  // throws if the pose is degenerate
    const vec3 right = cam.lens_u();
    const vec3 view = unit_vector(p.lookat - p.lookfrom);
    if (k > 0) {
      EXPECT_GT(glm::dot(right, previous_right), 0.99) << "frame " << k;
      EXPECT_GT(glm::dot(view, previous_view), 0.99) << "frame " << k;
    }
    previous_right = right;
    previous_view = view;
  }
  // Halfway the camera looks nearly straight down (the shortest rotation between the two frames
  // also rolls it, since their right vectors are opposite).
  const vec3 mid_view = unit_vector(path.at(0.5).lookat - path.at(0.5).lookfrom);
  EXPECT_GT(glm::dot(mid_view, vec3(0, -1, 0)), 0.95);
}

TEST(CameraPath, InvalidPathsAreRejected) {
  EXPECT_THROW(check_camera_path({camera_motion::orbit, book_pose(), 0, {}}),
               std::invalid_argument);
  EXPECT_THROW(check_camera_path({camera_motion::keyframes, {}, 0, {}}), std::invalid_argument);
  EXPECT_THROW(check_camera_path({camera_motion::keyframes,
                                  {},
                                  0,
                                  {key(1, point3(0, 0, 1), point3(0, 0, 0), 40),
                                   key(1, point3(0, 0, 2), point3(0, 0, 0), 40)}}),
               std::invalid_argument);
  EXPECT_THROW(
      check_camera_path({camera_motion::keyframes, {}, 0, {key(0, point3(0), point3(0), 40)}}),
      std::invalid_argument);
}

TEST(CameraPath, CameraNames) {
  EXPECT_TRUE(valid_camera_name("front-2_wide.v1"));
  EXPECT_FALSE(valid_camera_name(""));
  EXPECT_FALSE(valid_camera_name("all"));
  EXPECT_FALSE(valid_camera_name(".hidden"));
  EXPECT_FALSE(valid_camera_name("a/b"));
  EXPECT_FALSE(valid_camera_name("a b"));
  EXPECT_FALSE(valid_camera_name(std::string(65, 'a')));
}

}  // namespace
}  // namespace rtvk
