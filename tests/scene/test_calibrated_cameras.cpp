// The calibrated camera models (opencv, opencv-fisheye, fisheye-polynomial, cylindrical;
// docs/camera.md) on the CPU, in double: a pixel's ray projects back onto the pixel, known answers
// worked out from the formulas, the opencv inverse's convergence in double and in float (the GPU's
// arithmetic), the intrinsics' scaling to another image size, and keyframes that keep their lens.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "camera.h"
#include "camera_lens.h"
#include "camera_path.h"
#include "gpu/kernels_f32.h"
#include "scene.h"

namespace rtvk {
namespace {

constexpr double pi = 3.14159265358979323846;

// An aspect ratio that gives exactly `height` rows at `width` (the camera takes int(w / a)).
double exact_aspect(int width, int height) {
  double a = double(width) / height;
  while (int(width / a) < height) a = std::nextafter(a, 0.0);
  while (int(width / a) > height) a = std::nextafter(a, 1e300);
  return a;
}

camera make_camera(const camera_pose& pose, int width, int height) {
  const camera c(pose, exact_aspect(width, height), width);
  EXPECT_EQ(c.image_height(), height);
  return c;
}

// Each model with a lens of its own, in an oblique pose, for a 640x480 image.
camera_pose lens_pose(projection p) {
  camera_pose pose;
  pose.lookfrom = {1, 2, 3};
  pose.lookat = {0, 0.5, 0};
  pose.vup = {0.1, 1, 0};
  pose.projection = p;
  lens_intrinsics& l = pose.intrinsics;
  switch (p) {
    case projection::opencv:  // barrel, tangential and the rational terms all at work
      l = {0, 0, 500, 510, 322.5, 236.25, {-0.28, 0.07, 0.001, -0.0005, -0.01, 0.02, -0.01, 0.005}};
      break;
    case projection::opencv_fisheye:
      l = {0, 0, 300, 305, 318.5, 241.5, {0.05, -0.01, 0.002, -0.0003}};
      break;
    case projection::fisheye_polynomial:  // r in pixels; the image circle cuts the corners
      l = {0, 0, 0, 0, 318, 241, {0, 0.004, 1e-6, -2e-9, 0}};
      l.radius = 300;
      break;
    case projection::cylindrical:  // 4.3 radians across, tan(latitude) 1.2 up at the top
      l = {0, 0, 150, 200, 320, 240, {}};
      break;
    default:
      break;
  }
  return pose;
}

const projection calibrated_models[] = {projection::opencv, projection::opencv_fisheye,
                                        projection::fisheye_polynomial, projection::cylindrical};

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

vec3 unit(const vec3& v) {
  return v / glm::length(v);
}

// Every point on a pixel's ray projects back to the pixel (the forward model is the one
// cv::projectPoints computes, so the rays are the inverse of OpenCV's projection), over a grid of
// points across the whole image, edges included; nothing is lost but what the model cannot see.
TEST(CalibratedCameras, APointOnAPixelsRayProjectsBackToThePixel) {
  for (projection p : calibrated_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    const camera c = make_camera(lens_pose(p), 640, 480);
    const lens_intrinsics& l = lens_pose(p).intrinsics;
    int rays = 0, none = 0;
    double worst = 0;
    for (int gy = 0; gy <= 48; ++gy)
      for (int gx = 0; gx <= 64; ++gx) {
        const double x = -0.5 + gx * 10.0, y = -0.5 + gy * 10.0;
        const ray r = c.pixel_ray(x, y);
        if (r.direction == vec3(0)) {
          ++none;
          // Only the polynomial fisheye's image circle leaves pixels without a ray here.
          EXPECT_EQ(p, projection::fisheye_polynomial) << x << ", " << y;
          EXPECT_GT(std::hypot(x - l.cx, y - l.cy), l.radius) << x << ", " << y;
          continue;
        }
        ++rays;
        for (double distance : {0.01, 2.5, 1e4}) {
          const std::optional<glm::dvec2> back = c.project(r.origin + distance * r.direction);
          ASSERT_TRUE(back) << "pixel " << x << ", " << y << " at " << distance;
          worst = std::max({worst, std::abs(back->x - x), std::abs(back->y - y)});
          EXPECT_NEAR(back->x, x, 1e-9) << "pixel " << x << ", " << y;
          EXPECT_NEAR(back->y, y, 1e-9) << "pixel " << x << ", " << y;
        }
      }
    EXPECT_GT(rays, 2500);
    if (p == projection::fisheye_polynomial) {
      EXPECT_GT(none, 100);  // the corners
    }
    RecordProperty(std::string(projection_name(p)) + "_worst_px", shown(worst));
  }
}

// The angle from the view axis (-w) and the direction's turn about it, of a world direction.
struct polar {
  double theta, cos_phi, sin_phi;
};
polar polar_of(const vec3& d) {  // u = +x, v = +y, w = +z: the default pose
  const double across = std::hypot(d.x, d.y);
  return {std::atan2(across, -d.z), across > 0 ? d.x / across : 1, across > 0 ? d.y / across : 0};
}

// fisheye-polynomial with k1 alone is an equidistant fisheye: the angle from the axis is k1 r
// exactly, r the distance from (cx, cy) in pixels; and it sees what rtvk's ideal
// fisheye-equidistant model sees at the same angle (the ideal model's pixels are the lesson's
// s = i / (W - 1), so the two are compared at equal angles, not at equal pixels).
TEST(CalibratedCameras, APolynomialFisheyeWithK1AloneIsTheEquidistantFisheye) {
  camera_pose pose;
  pose.projection = projection::fisheye_polynomial;
  const double k1 = (pi / 2) / 150;  // 90 degrees at 150 pixels
  pose.intrinsics = {0, 0, 0, 0, 160.25, 119.75, {0, k1}};
  const camera poly = make_camera(pose, 320, 240);
  for (double y = -0.5; y <= 239.5; y += 7.75)
    for (double x = -0.5; x <= 319.5; x += 9.5) {
      const ray r = poly.pixel_ray(x, y);
      const double radius = std::hypot(x - 160.25, y - 119.75);
      if (k1 * radius > pi) {
        EXPECT_EQ(r.direction, vec3(0)) << "past straight back: " << x << ", " << y;
        continue;
      }
      const polar d = polar_of(r.direction);
      EXPECT_NEAR(d.theta, k1 * radius, 1e-12) << x << ", " << y;
      if (radius > 1e-9) {  // right is +x, down is -y
        EXPECT_NEAR(d.cos_phi, (x - 160.25) / radius, 1e-12) << x << ", " << y;
        EXPECT_NEAR(d.sin_phi, -(y - 119.75) / radius, 1e-12) << x << ", " << y;
      }
    }
  // The ideal model at 240 degrees, its directions found again by the polynomial.
  camera_pose ideal_pose;
  ideal_pose.projection = projection::fisheye_equidistant;
  ideal_pose.fisheye_fov = 240;
  const camera ideal(ideal_pose, 4.0 / 3.0, 320);
  int compared = 0;
  for (double t = 0; t <= 1; t += 1.0 / 16)
    for (double s = 0; s <= 1; s += 1.0 / 16) {
      const vec3 want = ideal.get_ray(s, t).direction;
      if (want == vec3(0)) continue;  // outside the ideal circle
      const polar d = polar_of(want);
      // Where the ideal's radius is r_ideal = theta / (fov / 2) in half image heights, the
      // polynomial's is theta / k1 in pixels.
      const double r = d.theta / k1;
      const vec3 got = poly.pixel_ray(160.25 + r * d.cos_phi, 119.75 - r * d.sin_phi).direction;
      ASSERT_NE(got, vec3(0));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(unit(got)[k], unit(want)[k], 1e-12) << s << ", " << t;
      ++compared;
    }
  EXPECT_GT(compared, 120);

  // Without coefficients: an equidistant fisheye of fisheye_fov over the circle that touches the
  // shorter side, centered on the image; nothing outside the circle.
  camera_pose plain;
  plain.projection = projection::fisheye_polynomial;
  plain.fisheye_fov = 180;
  const camera d = make_camera(plain, 320, 240);
  const auto expect_dir = [&](double x, double y, const vec3& want, const char* what) {
    const vec3 got = d.pixel_ray(x, y).direction;
    ASSERT_NE(got, vec3(0)) << what;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(unit(got)[k], want[k], 1e-12) << what;
  };
  expect_dir(159.5, 119.5, vec3(0, 0, -1), "the image center: the axis");
  expect_dir(159.5, -0.5, vec3(0, 1, 0), "the top edge's middle: 90 degrees up");
  expect_dir(159.5 - 120, 119.5, vec3(-1, 0, 0), "120 pixels left: 90 degrees left");
  expect_dir(159.5 + 60, 119.5, unit(vec3(1, 0, -1)), "60 pixels right: 45 degrees right");
  EXPECT_EQ(d.pixel_ray(159.5 + 121, 119.5).direction, vec3(0)) << "outside the circle";
  EXPECT_EQ(d.pixel_ray(0, 0).direction, vec3(0)) << "a corner";
}

// cylindrical: pixel (cx + fx phi, cy + fy h) looks at longitude phi and at height h on the unit
// cylinder (latitude atan(-h): y is down); uncalibrated, fisheye_fov across and vfov up.
TEST(CalibratedCameras, ACylinderMapsLongitudeAcrossAndHeightUp) {
  camera_pose pose;
  pose.projection = projection::cylindrical;
  pose.intrinsics = {0, 0, 150, 200, 160.25, 119.75, {}};
  const camera c = make_camera(pose, 320, 240);
  for (double phi : {-1.0, -0.3, 0.0, 0.5, 1.05})
    for (double h : {-0.55, -0.2, 0.0, 0.25, 0.59}) {
      const vec3 d = c.pixel_ray(160.25 + 150 * phi, 119.75 + 200 * h).direction;
      EXPECT_NEAR(std::atan2(d.x, -d.z), phi, 1e-13) << phi << ", " << h;
      EXPECT_NEAR(d.y / std::hypot(d.x, d.z), -h, 1e-13) << "tan(latitude) " << phi << ", " << h;
      const vec3 want = unit(vec3(std::sin(phi), -h, -std::cos(phi)));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(unit(d)[k], want[k], 1e-13);
    }
  // Past half a turn either way: nothing.
  camera_pose wide = pose;
  wide.intrinsics.fx = 40;  // 8 radians across
  const camera w = make_camera(wide, 320, 240);
  EXPECT_EQ(w.pixel_ray(160.25 + 40 * 3.2, 119.75).direction, vec3(0));
  EXPECT_NE(w.pixel_ray(160.25 + 40 * 3.1, 119.75).direction, vec3(0));

  camera_pose fields;
  fields.projection = projection::cylindrical;
  fields.fisheye_fov = 120;
  fields.vfov = 50;
  const camera f = make_camera(fields, 320, 240);
  const vec3 left = f.pixel_ray(-0.5, 119.5).direction;  // the left edge, halfway up
  EXPECT_NEAR(std::atan2(left.x, -left.z), -pi / 3, 1e-13);
  EXPECT_NEAR(left.y, 0, 1e-15);
  const vec3 top = f.pixel_ray(159.5, -0.5).direction;  // the top edge's middle
  EXPECT_NEAR(std::atan2(top.y, -top.z), 25 * pi / 180, 1e-13);
  EXPECT_NEAR(top.x, 0, 1e-15);
}

// opencv without distortion is a pinhole: direction ((x - cx) / fx, (y - cy) / fy, 1) in the
// camera's frame, x along u, y along -v, z along -w; and it is rtvk's perspective camera where
// the two put the image's outer pixel centers at the same angles.
TEST(CalibratedCameras, OpencvWithoutDistortionIsAPinhole) {
  camera_pose pose = lens_pose(projection::opencv);
  pose.intrinsics.k = {};
  const camera c = make_camera(pose, 640, 480);
  const vec3 u = c.lens_u(), v = c.lens_v(), w = c.axis_w();
  const lens_intrinsics& l = pose.intrinsics;
  for (double y : {-0.5, 0.0, 100.25, 236.25, 479.5})
    for (double x : {-0.5, 0.0, 322.5, 400.75, 639.5}) {
      const vec3 d = c.pixel_ray(x, y).direction;
      const vec3 want = (x - l.cx) / l.fx * u - (y - l.cy) / l.fy * v - w;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(d[k], want[k], 1e-15) << x << ", " << y;
    }
  // The perspective camera's s = x / (W - 1), t = 1 - y / (H - 1) spans the pixel centers, its
  // viewport 2 tan(vfov / 2) high: fy = (H - 1) / (2 tan(vfov / 2)), fx = fy, the center between.
  camera_pose persp = pose;
  persp.projection = projection::perspective;
  persp.intrinsics = {};
  persp.vfov = 50;
  const camera pc(persp, exact_aspect(640, 480), 640);
  const double aspect = pc.aspect_ratio();  // the viewport's width / height
  const double half = std::tan(25 * pi / 180);
  camera_pose pin = pose;
  pin.intrinsics = {0, 0, 639 / (2 * half * aspect), 479 / (2 * half), 319.5, 239.5, {}};
  const camera oc = make_camera(pin, 640, 480);
  for (double y : {0.0, 17.0, 239.5, 479.0})
    for (double x : {0.0, 100.0, 319.5, 639.0}) {
      const vec3 a = unit(oc.pixel_ray(x, y).direction);
      const vec3 b = unit(pc.get_ray(x / 639, 1 - y / 479).direction);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << x << ", " << y;
    }
}

// opencv's inverse (Newton's method, camera_rays.h): in double, the forward map of the point it
// finds is within 1e-12 of the target (normalized units) at every pixel of the image; in float,
// as the GPU computes, it converges too, to the float compilation's tolerance (16 float
// epsilons, relative: within 32 float ulps of the double answer).
TEST(CalibratedCameras, TheOpencvInverseConvergesInDoubleAndInFloat) {
  const camera c = make_camera(lens_pose(projection::opencv), 640, 480);
  const camera_frame& f = c.frame();
  double worst_double = 0, worst_float_ulps = 0, worst_float_residual = 0;
  const float eps_f = std::numeric_limits<float>::epsilon();
  for (int y = 0; y < 480; y += 3)
    for (int x = 0; x < 640; x += 3) {
      const real2 q((x - f.intrinsics.z) / f.intrinsics.x, (y - f.intrinsics.w) / f.intrinsics.y);
      real2 p, d_dx, d_dy;
      ASSERT_TRUE(opencv_undistort(f.distortion_a, f.distortion_b, q, f.lens_limit, p))
          << x << ", " << y;
      const real2 back = opencv_distort(f.distortion_a, f.distortion_b, p, d_dx, d_dy);
      const double err = std::max(std::abs(back.x - q.x), std::abs(back.y - q.y));
      worst_double = std::max(worst_double, err);
      EXPECT_LE(err, 1e-12) << x << ", " << y;

      glm::vec2 pf;
      const glm::vec4 ka(f.distortion_a), kb(f.distortion_b);
      ASSERT_TRUE(f32::opencv_undistort(ka, kb, glm::vec2(q), float(f.lens_limit), pf))
          << "float, " << x << ", " << y;
      const double scale = 1 + std::max(std::abs(p.x), std::abs(p.y));
      const double ulps = std::max(std::abs(pf.x - p.x), std::abs(pf.y - p.y)) / (eps_f * scale);
      worst_float_ulps = std::max(worst_float_ulps, ulps);
      // Newton stops once the residual is within 16 epsilons (lens_tolerance): up to 25 float
      // ulps of p measured where the lens compresses the image twofold (the bottom corners).
      EXPECT_LE(ulps, 32) << "float, " << x << ", " << y;
      // The float answer's residual, in double: the float compilation's tolerance, 16 epsilons
      // relative, plus the float rounding of the target and of the residual's own evaluation.
      const real2 fb = opencv_distort(f.distortion_a, f.distortion_b, real2(pf), d_dx, d_dy);
      const double residual = std::max(std::abs(fb.x - q.x), std::abs(fb.y - q.y));
      worst_float_residual = std::max(worst_float_residual, residual);
      EXPECT_LE(residual, 20 * double(eps_f) * (1 + std::max(std::abs(q.x), std::abs(q.y))))
          << "float, " << x << ", " << y;
    }
  RecordProperty("worst_double", shown(worst_double));
  RecordProperty("worst_float_ulps", shown(worst_float_ulps));
  RecordProperty("worst_float_residual", shown(worst_float_residual));
}

// Intrinsics calibrated at 640x480 and rendered at 320x240: a pixel's center scales about the
// image's corner ((c + 0.5) s - 0.5), so pixel (x, y) of the small image sees what point
// ((x + 0.5) 2 - 0.5, (y + 0.5) 2 - 0.5) of the calibrated one sees.
TEST(CalibratedCameras, IntrinsicsScaleWithTheImageAboutItsCorner) {
  for (projection p : calibrated_models) {
    SCOPED_TRACE(std::string(projection_name(p)));
    camera_pose calibrated = lens_pose(p);
    calibrated.intrinsics.width = 640;
    calibrated.intrinsics.height = 480;
    const camera big = make_camera(calibrated, 640, 480), small = make_camera(calibrated, 320, 240);
    for (double y : {-0.5, 0.0, 60.25, 119.5, 239.5})
      for (double x : {-0.5, 0.0, 80.75, 159.5, 319.5}) {
        const vec3 a = small.pixel_ray(x, y).direction;
        const vec3 b = big.pixel_ray((x + 0.5) * 2 - 0.5, (y + 0.5) * 2 - 0.5).direction;
        ASSERT_EQ(a == vec3(0), b == vec3(0)) << x << ", " << y;
        if (a == vec3(0)) continue;
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(unit(a)[k], unit(b)[k], 1e-12) << x << ", " << y;
      }
  }
  // The polynomial fisheye's default (no coefficients: fisheye_fov over the circle touching the
  // shorter side) is the same field whatever the size it is rendered at: its r is in the
  // calibration's pixels, and so is its circle.
  camera_pose plain;
  plain.projection = projection::fisheye_polynomial;
  const camera uncalibrated = make_camera(plain, 320, 240);
  plain.intrinsics = {640, 480, 0, 0, 319.5, 239.5, {}};
  const camera calibrated_plain = make_camera(plain, 320, 240);
  for (double y : {-0.5, 0.0, 30.0, 119.5, 239.5})
    for (double x : {-0.5, 40.0, 80.75, 159.5, 319.5}) {
      const vec3 a = uncalibrated.pixel_ray(x, y).direction;
      const vec3 b = calibrated_plain.pixel_ray(x, y).direction;
      ASSERT_EQ(a == vec3(0), b == vec3(0)) << x << ", " << y;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << x << ", " << y;
    }
  // Another aspect ratio than the calibration's is refused.
  camera_pose calibrated = lens_pose(projection::opencv);
  calibrated.intrinsics.width = 640;
  calibrated.intrinsics.height = 480;
  EXPECT_THROW(make_camera(calibrated, 640, 360), std::invalid_argument);
}

// Between two keyframes the earlier keyframe's lens holds, as its model does: intrinsics and
// the rolling shutter are not lost to the defaults (which an opencv camera cannot render).
TEST(CalibratedCameras, KeyframesKeepTheEarlierKeyframesLens) {
  camera_path path;
  path.motion = camera_motion::keyframes;
  camera_pose a = lens_pose(projection::opencv), b = a;
  a.readout = 0.02;
  b.lookfrom = {2, 2, 3};
  b.intrinsics.fx = 600;
  path.keyframes = {{0.0, a}, {1.0, b}};
  const camera_pose mid = path.at(0.5);
  EXPECT_EQ(mid.projection, projection::opencv);
  EXPECT_EQ(mid.intrinsics, a.intrinsics);
  EXPECT_EQ(mid.readout, a.readout);
  EXPECT_NO_THROW(make_camera(mid, 640, 480));
}

// What a user gives stays when the rest is made up: a polynomial fisheye's image circle, a
// cylinder's center (both were overwritten by the defaults once).
TEST(CalibratedCameras, AGivenImageCircleAndCylinderCenterStay) {
  camera_pose poly;
  poly.projection = projection::fisheye_polynomial;
  poly.intrinsics.radius = 50;  // no coefficients: equidistant over this circle
  const camera p = make_camera(poly, 320, 240);
  const double cx = 159.5, cy = 119.5;
  EXPECT_NE(p.pixel_ray(cx + 49, cy).direction, vec3(0));
  EXPECT_EQ(p.pixel_ray(cx + 51, cy).direction, vec3(0));  // past the circle: nothing
  // At the circle's edge, half the field of view (180 degrees by default) from the axis.
  const vec3 edge = glm::normalize(p.pixel_ray(cx + 50, cy).direction);
  EXPECT_NEAR(std::acos(glm::dot(edge, -p.axis_w())), pi / 2, 1e-12);

  camera_pose cyl;
  cyl.projection = projection::cylindrical;
  cyl.intrinsics.cx = 40;
  cyl.intrinsics.cy = 30;  // fx, fy from the fields of view; this center
  const camera c = make_camera(cyl, 320, 240);
  const vec3 ahead = glm::normalize(c.pixel_ray(40, 30).direction);
  EXPECT_NEAR(glm::length(ahead + c.axis_w()), 0, 1e-12);
}

// Review findings, each seen failing before its fix: the viewer's motion span reaches a rolling
// shutter's last row; a polynomial fisheye with only a calibration size is centered on it.
TEST(CalibratedCameras, TheMotionSpanAndTheDefaultCenterFollowTheLens) {
  scene s;
  camera_pose& p = s.cameras[0].path.pose;
  p.shutter_close = 1;
  p.readout = -0.02;  // bottom row first: the top row opens 0.02 s later
  EXPECT_DOUBLE_EQ(shutter_span(s, 0).hi, 1.02);

  camera_pose poly;
  poly.projection = projection::fisheye_polynomial;
  poly.intrinsics.width = 640;
  poly.intrinsics.height = 480;  // no center, no coefficients: the calibration's image center
  const camera c = make_camera(poly, 320, 240);
  const vec3 ahead = glm::normalize(c.pixel_ray(159.5, 119.5).direction);
  EXPECT_NEAR(glm::length(ahead + c.axis_w()), 0, 1e-12);
}

}  // namespace
}  // namespace rtvk
