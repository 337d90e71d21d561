#include "camera_controls.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace rtvk::view {
namespace {

constexpr double degrees = 3.14159265358979323846 / 180;

vec3 rotate(const vec3& v, const vec3& axis, double radians) {
  const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), radians, glm::normalize(axis));
  return vec3(r * glm::dvec4(v, 0.0));
}

}  // namespace

camera_pose orbit(const camera_pose& p, double right_px, double up_px) {
  camera_pose out = p;
  const vec3 up = glm::normalize(p.vup);
  vec3 offset = p.lookfrom - p.lookat;  // from the target to the eye
  offset = rotate(offset, up, right_px * orbit_degrees_per_pixel * degrees);
  // Pitch about the camera's right axis, clamped away from vup and -vup.
  const double length = glm::length(offset);
  const double polar = std::acos(std::clamp(glm::dot(offset / length, up), -1.0, 1.0));
  const double wanted =
      std::clamp(polar - up_px * orbit_degrees_per_pixel * degrees, 1 * degrees, 179 * degrees);
  // Rotating about up x offset by a positive angle tilts the offset away from up.
  const vec3 axis = glm::cross(up, offset);
  if (glm::length(axis) > 0) offset = rotate(offset, axis, wanted - polar);
  out.lookfrom = p.lookat + offset;
  return out;
}

camera_pose pan(const camera_pose& p, double right_px, double up_px, int height_px) {
  camera_pose out = p;
  const vec3 w = glm::normalize(p.lookfrom - p.lookat);
  const vec3 u = glm::normalize(glm::cross(p.vup, w));
  const vec3 v = glm::cross(w, u);
  const double distance = glm::length(p.lookfrom - p.lookat);
  // Scene units per pixel at the look-at distance.
  const double scale = 2 * distance * std::tan(p.vfov * degrees / 2) / std::max(height_px, 1);
  const vec3 move = -right_px * scale * u - up_px * scale * v;
  out.lookfrom += move;
  out.lookat += move;
  return out;
}

camera_pose dolly(const camera_pose& p, double steps) {
  camera_pose out = p;
  const vec3 offset = p.lookfrom - p.lookat;
  out.lookfrom = p.lookat + offset * std::pow(dolly_per_wheel_step, steps);
  return out;
}

camera_pose fly(const camera_pose& p, double forward, double right, double up) {
  camera_pose out = p;
  const vec3 w = glm::normalize(p.lookfrom - p.lookat);
  const vec3 u = glm::normalize(glm::cross(p.vup, w));
  const double step = fly_fraction * glm::length(p.lookfrom - p.lookat);
  const vec3 move = step * (-forward * w + right * u + up * glm::normalize(p.vup));
  out.lookfrom += move;
  out.lookat += move;
  return out;
}

camera_pose zoom(const camera_pose& p, double steps) {
  camera_pose out = p;
  out.vfov = std::clamp(p.vfov - steps * fov_step_degrees, 1.0, 179.0);
  return out;
}

camera_pose stop(const camera_pose& p, int steps) {
  camera_pose out = p;
  if (!has_lens(p.projection)) return out;
  double a = p.aperture;
  for (int i = 0; i < steps; ++i) a = a == 0 ? 0.01 : a * aperture_step;
  for (int i = 0; i > steps; --i) a = a <= 0.01 ? 0 : a / aperture_step;
  out.aperture = a;
  return out;
}

camera_pose next_projection(const camera_pose& p) {
  camera_pose out = p;
  switch (p.projection) {
    case projection::perspective:
      out.projection = projection::orthographic;
      break;
    case projection::orthographic:
      out.projection = projection::equirectangular;
      break;
    case projection::equirectangular:
      out.projection = projection::fisheye_equidistant;
      break;
    case projection::fisheye_equidistant:
      out.projection = projection::fisheye_equisolid;
      break;
    case projection::fisheye_equisolid:
      out.projection = projection::cylindrical;
      out.intrinsics = {};  // uncalibrated: its fields of view make the intrinsics
      break;
    case projection::cylindrical:  // (uncalibrated: fields of view make its intrinsics)
    case projection::opencv:       // the calibrated lenses leave the cycle for the pinhole
    case projection::opencv_fisheye:
    case projection::fisheye_polynomial:
      out.projection = projection::perspective;
      break;
  }
  if (!has_lens(out.projection)) out.aperture = 0;
  return out;
}

}  // namespace rtvk::view
