#include "camera_lens.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "format.h"

namespace rtvk {
namespace {

std::string coefficients(const lens_intrinsics& l, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? "," : "") + format_number(l.k[std::size_t(i)]);
  return out;
}

void check_finite(const camera_pose& pose) {
  const lens_intrinsics& l = pose.intrinsics;
  bool ok = std::isfinite(l.fx) && std::isfinite(l.fy) && std::isfinite(l.cx) &&
            std::isfinite(l.cy) && std::isfinite(l.radius) && l.radius >= 0;
  for (double k : l.k) ok = ok && std::isfinite(k);
  if (!ok)
    throw std::invalid_argument("the " + std::string(projection_name(pose.projection)) +
                                " intrinsics must be finite (fx " + format_number(l.fx) + ", fy " +
                                format_number(l.fy) + ", cx " + format_number(l.cx) + ", cy " +
                                format_number(l.cy) + ", distortion " + coefficients(l, 8) +
                                ", radius " + format_number(l.radius) + ")");
  if (l.width < 0 || l.height < 0 || (l.width == 0) != (l.height == 0))
    throw std::invalid_argument("the calibration's image size " + std::to_string(l.width) + "x" +
                                std::to_string(l.height) + " is not a size");
}

// The intrinsics of an uncalibrated cylinder or polynomial fisheye, from the pose's fields of
// view: a cylinder fisheye_fov across and vfov high; an equidistant fisheye of fisheye_fov
// across the circle that touches the shorter side.
lens_intrinsics default_intrinsics(const camera_pose& pose, int width, int height) {
  lens_intrinsics l = pose.intrinsics;
  const double across = pose.fisheye_fov * pi / 180;
  if (pose.projection == projection::cylindrical && l.fx == 0 && l.fy == 0) {
    l.fx = width / across;
    l.fy = (height / 2.0) / std::tan(pose.vfov * pi / 360);
    if (l.cx == 0 && l.cy == 0) {  // a center given stays
      l.cx = (width - 1) / 2.0;
      l.cy = (height - 1) / 2.0;
    }
    l.width = l.height = 0;
  }
  if (pose.projection == projection::fisheye_polynomial) {
    const bool no_polynomial = std::all_of(l.k.begin(), l.k.end(), [](double k) { return k == 0; });
    if (l.cx == 0 && l.cy == 0) {  // the center of the image the intrinsics are for
      l.cx = ((l.width > 0 ? l.width : width) - 1) / 2.0;
      l.cy = ((l.height > 0 ? l.height : height) - 1) / 2.0;
    }
    if (no_polynomial) {  // r is in the calibration's pixels, where there is a calibration
      if (l.radius == 0)  // an image circle given stays
        l.radius = (l.width > 0 ? std::min(l.width, l.height) : std::min(width, height)) / 2.0;
      l.k[1] = across / 2 / l.radius;
    }
  }
  return l;
}

// The largest undistorted radius^2 up to which OpenCV's radial map r -> r radial(r^2) keeps
// increasing with a positive denominator: past it, the map folds and the inverse is not unique.
double opencv_fold_radius2(const real4& ka, const real4& kb) {
  constexpr double largest = 20, step = 1.0 / 4096;  // 87 degrees from the axis
  for (double r = step; r <= largest; r += step) {
    real2 d_dx, d_dy;
    const real2 along = opencv_distort(real4(ka.x, ka.y, 0, 0), kb, real2(r, 0), d_dx, d_dy);
    const double r2 = r * r;
    const double b = 1 + r2 * (kb.y + r2 * (kb.z + r2 * kb.w));
    if (!(d_dx.x > 0) || !(b > 0) || !std::isfinite(along.x)) {
      const double before = r - step;
      return before * before;
    }
  }
  return largest * largest;
}

// The image's outer edge (where the border pixels' samples reach, half a pixel past their
// centers) and every pixel center of a grid inside must invert: the distortion is then
// invertible over the image (a fold inside the image would leave a point with no ray, or two).
void check_opencv_inverts(const camera_frame& f, const camera_pose& pose, int width, int height) {
  const auto check = [&](double x, double y) {
    const real2 q((x - f.intrinsics.z) / f.intrinsics.x, (y - f.intrinsics.w) / f.intrinsics.y);
    real2 p;
    if (opencv_undistort(f.distortion_a, f.distortion_b, q, f.lens_limit, p)) return;
    throw std::invalid_argument("the opencv distortion " + coefficients(pose.intrinsics, 8) +
                                " is not invertible over the image: its point (" +
                                format_number(x) + ", " + format_number(y) +
                                ") has no undistorted point before the lens folds (radius " +
                                format_number(std::sqrt(f.lens_limit)) + " in normalized units)");
  };
  const double left = -0.5, top = -0.5, right = width - 0.5, bottom = height - 0.5;
  for (int x = 0; x <= width; ++x) {
    check(x - 0.5, top);
    check(x - 0.5, bottom);
  }
  for (int y = 0; y <= height; ++y) {
    check(left, y - 0.5);
    check(right, y - 0.5);
  }
  for (int y = 0; y < height; y += 16)
    for (int x = 0; x < width; x += 16) check(x, y);
}

}  // namespace

void setup_lens(const camera_pose& pose, int width, int height, camera_frame& f) {
  check_finite(pose);
  const lens_intrinsics l = default_intrinsics(pose, width, height);
  const std::string name(projection_name(pose.projection));
  double sx = 1, sy = 1;  // the render's pixels per calibration pixel
  if (l.width > 0) {
    sx = double(width) / l.width;
    sy = double(height) / l.height;
    if (std::abs(height - l.height * sx) > 1)
      throw std::invalid_argument("the calibration is for " + std::to_string(l.width) + "x" +
                                  std::to_string(l.height) + " pixels; a " + std::to_string(width) +
                                  "x" + std::to_string(height) +
                                  " render has another aspect ratio");
  }
  const bool polynomial = pose.projection == projection::fisheye_polynomial;
  if (!polynomial && !(l.fx > 0 && l.fy > 0))
    throw std::invalid_argument("the " + name + " model needs focal lengths fx, fy > 0 pixels (" +
                                "--calibration or --intrinsics), got " + format_number(l.fx) +
                                ", " + format_number(l.fy));
  // A pixel's center scales about the image's corner: (c + 0.5) s - 0.5.
  const double cx = (l.cx + 0.5) * sx - 0.5, cy = (l.cy + 0.5) * sy - 0.5;
  f.intrinsics = polynomial ? real4(sx, sy, cx, cy) : real4(l.fx * sx, l.fy * sy, cx, cy);
  f.distortion_a = real4(l.k[0], l.k[1], l.k[2], l.k[3]);
  f.distortion_b = real4(l.k[4], l.k[5], l.k[6], l.k[7]);
  f.lens_limit = 0;
  f.lens_angle = 0;
  if (pose.projection == projection::opencv) {
    f.lens_limit = opencv_fold_radius2(f.distortion_a, f.distortion_b);
    check_opencv_inverts(f, pose, width, height);
  } else if (pose.projection == projection::opencv_fisheye) {
    // OpenCV's model covers the half space in front (theta < 90 degrees), up to a fold.
    double theta = 0, slope = 1;
    constexpr double step = 1.0 / 4096;
    while (theta + step < pi / 2) {
      fisheye_distort(f.distortion_a, theta + step, slope);
      if (!(slope > 0)) break;
      theta += step;
    }
    f.lens_angle = theta;
    f.lens_limit = fisheye_distort(f.distortion_a, theta, slope);
  } else if (polynomial) {
    f.lens_limit = l.radius;
  }
}

std::optional<glm::dvec2> project_calibrated(const camera_frame& f, const glm::dvec3& c) {
  const glm::dvec4 in = f.intrinsics;
  switch (f.projection) {
    case RTVK_PROJECTION_OPENCV: {
      if (!(c.z > 0)) return std::nullopt;
      const real2 p(c.x / c.z, c.y / c.z);
      if (p.x * p.x + p.y * p.y > f.lens_limit) return std::nullopt;
      real2 d_dx, d_dy;
      const real2 d = opencv_distort(f.distortion_a, f.distortion_b, p, d_dx, d_dy);
      return glm::dvec2(in.x * d.x + in.z, in.y * d.y + in.w);
    }
    case RTVK_PROJECTION_OPENCV_FISHEYE: {
      const double r = std::hypot(c.x, c.y);
      const double theta = std::atan2(r, c.z);
      if (theta > f.lens_angle) return std::nullopt;
      double slope;
      const double theta_d = fisheye_distort(f.distortion_a, theta, slope);
      const double scale = r > 0 ? theta_d / r : 0;
      return glm::dvec2(in.x * c.x * scale + in.z, in.y * c.y * scale + in.w);
    }
    case RTVK_PROJECTION_CYLINDRICAL: {
      const double around = std::hypot(c.x, c.z);
      if (!(around > 0)) return std::nullopt;
      return glm::dvec2(in.x * std::atan2(c.x, c.z) + in.z, in.y * c.y / around + in.w);
    }
    case RTVK_PROJECTION_FISHEYE_POLYNOMIAL: {
      // The radius whose angle is theta, by bisection: the polynomial need not have an inverse
      // in closed form, and increases over the field the tests use.
      const double r_xy = std::hypot(c.x, c.y), theta = std::atan2(r_xy, c.z);
      const glm::dvec4 k = f.distortion_a;
      const double k4 = f.distortion_b.x;
      const auto angle = [&](double r) { return k.x + r * (k.y + r * (k.z + r * (k.w + r * k4))); };
      double lo = 0, hi = f.lens_limit > 0 ? f.lens_limit : 1e6;
      if (theta < angle(lo) || theta > angle(hi)) return std::nullopt;
      for (int n = 0; n < 200; ++n) (angle((lo + hi) / 2) < theta ? lo : hi) = (lo + hi) / 2;
      const double r = (lo + hi) / 2;
      const double ux = r_xy > 0 ? c.x / r_xy : 0, uy = r_xy > 0 ? c.y / r_xy : 0;
      return glm::dvec2(in.x * r * ux + in.z, in.y * r * uy + in.w);
    }
    default:
      return std::nullopt;
  }
}

}  // namespace rtvk
