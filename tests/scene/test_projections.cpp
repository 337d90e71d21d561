// Camera projections (host/camera/camera.h, docs/camera.md): known answers worked out by hand,
// round trips through an inverse written here independently of the camera, and the apparent size
// of a sphere in rendered images.
#include <gtest/gtest.h>

#include <cmath>

#include "camera.h"
#include "render_cpu.h"
#include "render_helpers.h"

namespace rtvk {
namespace {

constexpr double pi = 3.14159265358979323846;

// A camera at the origin looking down -z (u = +x, v = +y, w = +z), with the given model.
camera posed(projection p, double aspect = 2, int width = 201, double fisheye_fov = 180) {
  camera_pose pose;
  pose.projection = p;
  pose.fisheye_fov = fisheye_fov;
  return camera(pose, aspect, width);
}

void expect_direction(const camera& c, double s, double t, const vec3& want, const char* what) {
  const vec3 d = unit_vector(c.get_ray(s, t).direction);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[k], want[k], 1e-12) << what << ", component " << k;
}

TEST(Projection, EveryModelLooksAlongMinusWAtTheImageCenter) {
  for (projection p :
       {projection::perspective, projection::orthographic, projection::equirectangular,
        projection::fisheye_equidistant, projection::fisheye_equisolid})
    expect_direction(posed(p), 0.5, 0.5, vec3(0, 0, -1), std::string(projection_name(p)).c_str());
}

TEST(Projection, EquirectangularEdgesLookBehindAndThePolesUpAndDown) {
  const camera c = posed(projection::equirectangular);
  expect_direction(c, 0.0, 0.5, vec3(0, 0, 1), "left edge: straight behind");
  expect_direction(c, 1.0, 0.5, vec3(0, 0, 1), "right edge: straight behind");
  expect_direction(c, 0.75, 0.5, vec3(1, 0, 0), "three quarters across: to the right");
  expect_direction(c, 0.25, 0.5, vec3(-1, 0, 0), "a quarter across: to the left");
  expect_direction(c, 0.5, 1.0, vec3(0, 1, 0), "top: straight up");
  expect_direction(c, 0.3, 0.0, vec3(0, -1, 0), "bottom: straight down");
}

TEST(Projection, FisheyeAnglesGrowWithTheRadiusAsEachModelSays) {
  // aspect 2: x = (2s - 1) * 2, y = 2t - 1. The top edge's middle is r = 1.
  const camera eq = posed(projection::fisheye_equidistant);
  const camera es = posed(projection::fisheye_equisolid);
  expect_direction(eq, 0.5, 1.0, vec3(0, 1, 0), "equidistant, r = 1 at 180 degrees: 90 off axis");
  expect_direction(es, 0.5, 1.0, vec3(0, 1, 0), "equisolid, r = 1 at 180 degrees: 90 off axis");
  // r = 0.5 to the right (s = 0.625): equidistant 45 degrees; equisolid 2 asin(0.5 sin 45).
  expect_direction(eq, 0.625, 0.5, vec3(std::sin(pi / 4), 0, -std::cos(pi / 4)), "equidistant");
  const double th = 2 * std::asin(0.5 * std::sin(pi / 4));
  expect_direction(es, 0.625, 0.5, vec3(std::sin(th), 0, -std::cos(th)), "equisolid");
  // 360 degrees: the rim looks straight back.
  expect_direction(posed(projection::fisheye_equidistant, 2, 201, 360), 0.5, 0.0, vec3(0, 0, 1),
                   "equidistant 360, bottom rim: straight behind");
  // Outside the circle: no ray.
  EXPECT_EQ(eq.get_ray(0.0, 0.0).direction, vec3(0, 0, 0));
  EXPECT_EQ(es.get_ray(0.05, 0.5).direction, vec3(0, 0, 0));
}

TEST(Projection, OrthographicRaysAreParallelFromTheFocusPlaneViewport) {
  camera_pose pose;
  pose.projection = projection::orthographic;
  pose.vfov = 60;
  pose.focus_dist = 3;
  const camera c(pose, 1.5, 151);
  // Viewport height 2 * 3 * tan(30 degrees), width 1.5 times that.
  const double h = 6 * std::tan(pi / 6), w = 1.5 * h;
  for (auto [s, t] : {std::pair{0.0, 0.0}, {1.0, 1.0}, {0.25, 0.8}}) {
    const ray r = c.get_ray(s, t);
    EXPECT_NEAR(r.origin.x, (s - 0.5) * w, 1e-12);
    EXPECT_NEAR(r.origin.y, (t - 0.5) * h, 1e-12);
    EXPECT_NEAR(r.origin.z, 0, 1e-12);
    expect_direction(c, s, t, vec3(0, 0, -1), "orthographic");
  }
}

// Inverses written from the model's definition (docs/camera.md), for a unit direction d in the
// frame u = +x, v = +y, w = +z.
std::pair<double, double> equirect_inverse(const vec3& d) {
  const double phi = std::atan2(d.x, -d.z), theta = std::asin(d.y);
  return {phi / (2 * pi) + 0.5, theta / pi + 0.5};
}
std::pair<double, double> fisheye_inverse(const vec3& d, bool equisolid, double fov,
                                          double aspect) {
  const double theta = std::acos(-d.z);
  const double r = equisolid ? std::sin(theta / 2) / std::sin(fov / 4) : theta / (fov / 2);
  const double len = std::hypot(d.x, d.y);
  const double x = len > 0 ? r * d.x / len : 0, y = len > 0 ? r * d.y / len : 0;
  return {(x / aspect + 1) / 2, (y + 1) / 2};
}

TEST(Projection, DirectionsMapBackToTheImagePointsTheyCameFrom) {
  const double aspect = 2;
  for (double fov_deg : {120.0, 180.0, 270.0}) {
    const camera eq = posed(projection::fisheye_equidistant, aspect, 201, fov_deg);
    const camera es = posed(projection::fisheye_equisolid, aspect, 201, fov_deg);
    for (double s = 0.3; s <= 0.7; s += 0.05)
      for (double t = 0.1; t <= 0.9; t += 0.05) {
        for (const camera* c : {&eq, &es}) {
          const vec3 d = unit_vector(c->get_ray(s, t).direction);
          if (d != d || glm::length(c->get_ray(s, t).direction) == 0) continue;
          const auto [s2, t2] = fisheye_inverse(d, c == &es, fov_deg * pi / 180, aspect);
          EXPECT_NEAR(s2, s, 1e-9) << "fov " << fov_deg << " at " << s << ", " << t;
          EXPECT_NEAR(t2, t, 1e-9) << "fov " << fov_deg << " at " << s << ", " << t;
        }
      }
  }
  const camera er = posed(projection::equirectangular);
  for (double s = 0.02; s < 1; s += 0.05)
    for (double t = 0.02; t < 1; t += 0.05) {
      const auto [s2, t2] = equirect_inverse(unit_vector(er.get_ray(s, t).direction));
      EXPECT_NEAR(s2, s, 1e-9) << s << ", " << t;
      EXPECT_NEAR(t2, t, 1e-9) << s << ", " << t;
    }
}

// The seed's sphere (radius 0.5, 1 unit ahead: 60 degrees across) on a black sky, no ground:
// how many pixels of the middle row it covers.
int sphere_width(projection p, double aspect, int width) {
  scene s = builtin_scene("seed");
  s.spheres.resize(1);  // the sphere, not the ground
  s.sky = {color(0, 0, 0), color(0, 0, 0)};
  camera_pose pose;
  pose.projection = p;
  const camera c(pose, aspect, width);
  const framebuffer fb = render_cpu(c, s, s.render);
  const int row = c.image_height() / 2;
  int n = 0;
  for (int x = 0; x < fb.width(); ++x) n += fb.at(x, row) != color(0, 0, 0);
  return n;
}

TEST(Projection, TheSeedsSphereHasItsTrueApparentSize) {
  // Equirectangular, 601 wide: 360 degrees over 600 pixel steps, so 60 degrees are 100 steps.
  EXPECT_NEAR(sphere_width(projection::equirectangular, 601.0 / 301.0, 601), 101, 1);
  // Equidistant fisheye, 180 degrees, square 301: 90 degrees over 150 pixels, 30 over 50.
  EXPECT_NEAR(sphere_width(projection::fisheye_equidistant, 1, 301), 101, 1);
  // Orthographic: the viewport is 2 units wide at aspect 1 (vfov 90, focus 1) over 300 steps,
  // and the sphere's true diameter is 1 unit: 150 steps.
  EXPECT_NEAR(sphere_width(projection::orthographic, 1, 301), 151, 1);
  // Perspective, for contrast: tan(30 degrees) of the half-width 1: 0.577 * 150 steps a side.
  EXPECT_NEAR(sphere_width(projection::perspective, 1, 301), 2 * 86.6 + 1, 2);
}

TEST(Projection, NamesRoundTripAndBadPosesAreRefused) {
  for (projection p :
       {projection::perspective, projection::orthographic, projection::equirectangular,
        projection::fisheye_equidistant, projection::fisheye_equisolid})
    EXPECT_EQ(projection_from_name(projection_name(p)), p);
  EXPECT_FALSE(projection_from_name("fisheye"));
  camera_pose pose;
  pose.projection = projection::fisheye_equisolid;
  pose.aperture = 0.1;
  EXPECT_THROW(camera(pose, 1, 10), std::invalid_argument);
  pose.aperture = 0;
  pose.fisheye_fov = 361;
  EXPECT_THROW(camera(pose, 1, 10), std::invalid_argument);
  pose.fisheye_fov = 0;
  EXPECT_THROW(camera(pose, 1, 10), std::invalid_argument);
  pose.projection = projection::orthographic;
  pose.fisheye_fov = 180;
  pose.aperture = 0.1;  // the thin lens applies to orthographic cameras
  EXPECT_NO_THROW(camera(pose, 1, 10));
}

}  // namespace
}  // namespace rtvk
