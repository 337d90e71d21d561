#include "camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "format.h"

namespace rtvk {
namespace {

int checked_height(double aspect_ratio, int image_width) {
  if (!std::isfinite(aspect_ratio) || aspect_ratio <= 0)
    throw std::invalid_argument("aspect ratio must be finite and > 0, got " +
                                format_number(aspect_ratio));
  if (image_width < 1 || image_width > max_image_side)
    throw std::invalid_argument("image width must be in [1, " + std::to_string(max_image_side) +
                                "], got " + std::to_string(image_width));
  // Checked in double first: int() of an out-of-range value is undefined behaviour.
  const double height = image_width / aspect_ratio;
  if (height >= max_image_side + 1.0)
    throw std::invalid_argument("aspect ratio " + format_number(aspect_ratio) + " at width " +
                                std::to_string(image_width) + " gives an image height above " +
                                std::to_string(max_image_side));
  return std::max(1, static_cast<int>(height));
}

bool finite(const vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_pose(const camera_pose& p) {
  if (!finite(p.lookfrom) || !finite(p.lookat) || !finite(p.vup))
    throw std::invalid_argument("camera position, look-at point and up vector must be finite");
  if (!(p.vfov > 0 && p.vfov < 180))
    throw std::invalid_argument("vertical field of view must be in (0, 180) degrees, got " +
                                format_number(p.vfov));
  if (!(p.aperture >= 0) || !std::isfinite(p.aperture))
    throw std::invalid_argument("aperture must be finite and >= 0, got " +
                                format_number(p.aperture));
  if (!(p.focus_dist > 0) || !std::isfinite(p.focus_dist))
    throw std::invalid_argument("focus distance must be finite and > 0, got " +
                                format_number(p.focus_dist));
  if (glm::length(p.lookfrom - p.lookat) == 0)
    throw std::invalid_argument("lookfrom and lookat are the same point");
  if (glm::length(glm::cross(p.vup, p.lookfrom - p.lookat)) == 0)
    throw std::invalid_argument("the up vector is zero or parallel to the viewing direction");
}

// tan(vfov / 2). 90 degrees gives exactly 1, as in the lesson's viewport of height 2:
// std::tan(pi / 4) rounds to 1 - 2^-53, which would move pixels of the lesson's image.
double tan_half_angle(double vfov_degrees) {
  if (vfov_degrees == 90) return 1.0;
  return std::tan(vfov_degrees * 3.1415926535897932385 / 180.0 / 2.0);
}

}  // namespace

camera::camera(const camera_pose& pose, double aspect_ratio, int image_width)
    : aspect_ratio_(aspect_ratio),
      image_width_(image_width),
      image_height_(checked_height(aspect_ratio, image_width)) {
  check_pose(pose);
  const double viewport_height = 2.0 * tan_half_angle(pose.vfov);
  const double viewport_width = aspect_ratio * viewport_height;

  const vec3 w = unit_vector(pose.lookfrom - pose.lookat);
  const vec3 u = unit_vector(glm::cross(pose.vup, w));
  const vec3 v = glm::cross(w, u);

  origin_ = pose.lookfrom;
  horizontal_ = pose.focus_dist * viewport_width * u;
  vertical_ = pose.focus_dist * viewport_height * v;
  lower_left_ = origin_ - divide(horizontal_, 2) - divide(vertical_, 2) - pose.focus_dist * w;
  lens_u_ = u;
  lens_v_ = v;
  lens_radius_ = pose.aperture / 2;
}

}  // namespace rtvk
