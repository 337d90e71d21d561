#include "camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "camera_lens.h"
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
  if (!(p.fisheye_fov > 0 && p.fisheye_fov <= 360))
    throw std::invalid_argument("fisheye field of view must be in (0, 360] degrees, got " +
                                format_number(p.fisheye_fov));
  if (p.aperture > 0 && !has_lens(p.projection))
    throw std::invalid_argument("the " + std::string(projection_name(p.projection)) +
                                " projection has no lens: aperture must be 0, got " +
                                format_number(p.aperture));
  if (!std::isfinite(p.shutter_open) || !std::isfinite(p.shutter_close) ||
      !(p.shutter_open <= p.shutter_close))
    throw std::invalid_argument("the shutter must open (" + format_number(p.shutter_open) +
                                " s) no later than it closes (" + format_number(p.shutter_close) +
                                " s), both finite");
  if (!std::isfinite(p.readout))
    throw std::invalid_argument("the rolling shutter's readout must be finite, got " +
                                format_number(p.readout));
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

struct named_projection {
  projection model;
  std::string_view name;
};
constexpr named_projection projections[] = {
    {projection::perspective, "perspective"},
    {projection::orthographic, "orthographic"},
    {projection::equirectangular, "equirectangular"},
    {projection::fisheye_equidistant, "fisheye-equidistant"},
    {projection::fisheye_equisolid, "fisheye-equisolid"},
    {projection::opencv, "opencv"},
    {projection::opencv_fisheye, "opencv-fisheye"},
    {projection::fisheye_polynomial, "fisheye-polynomial"},
    {projection::cylindrical, "cylindrical"},
};

}  // namespace

static_assert(int(projection::perspective) == RTVK_PROJECTION_PERSPECTIVE);
static_assert(int(projection::orthographic) == RTVK_PROJECTION_ORTHOGRAPHIC);
static_assert(int(projection::equirectangular) == RTVK_PROJECTION_EQUIRECTANGULAR);
static_assert(int(projection::fisheye_equidistant) == RTVK_PROJECTION_FISHEYE_EQUIDISTANT);
static_assert(int(projection::fisheye_equisolid) == RTVK_PROJECTION_FISHEYE_EQUISOLID);
static_assert(int(projection::opencv) == RTVK_PROJECTION_OPENCV);
static_assert(int(projection::opencv_fisheye) == RTVK_PROJECTION_OPENCV_FISHEYE);
static_assert(int(projection::fisheye_polynomial) == RTVK_PROJECTION_FISHEYE_POLYNOMIAL);
static_assert(int(projection::cylindrical) == RTVK_PROJECTION_CYLINDRICAL);

std::string_view projection_name(projection p) {
  for (const named_projection& n : projections)
    if (n.model == p) return n.name;
  return "unknown";
}

std::optional<projection> projection_from_name(std::string_view name) {
  for (const named_projection& n : projections)
    if (n.name == name) return n.model;
  return std::nullopt;
}

std::string projection_names() {
  std::string out;
  for (const named_projection& n : projections)
    out += (out.empty() ? "" : ", ") + std::string(n.name);
  return out;
}

camera::camera(const camera_pose& pose, double aspect_ratio, int image_width, double frame_time)
    : image_width_(image_width), image_height_(checked_height(aspect_ratio, image_width)) {
  check_pose(pose);
  if (!std::isfinite(frame_time + pose.shutter_open) ||
      !std::isfinite(frame_time + pose.shutter_close))
    throw std::invalid_argument("the shutter's times must be finite");
  const double viewport_height = 2.0 * tan_half_angle(pose.vfov);
  const double viewport_width = aspect_ratio * viewport_height;

  const vec3 w = unit_vector(pose.lookfrom - pose.lookat);
  const vec3 u = unit_vector(glm::cross(pose.vup, w));
  const vec3 v = glm::cross(w, u);

  camera_frame& f = frame_;
  f.origin = pose.lookfrom;
  f.horizontal = pose.focus_dist * viewport_width * u;
  f.vertical = pose.focus_dist * viewport_height * v;
  // From the eye to the lower-left corner without going through the scene's origin: no
  // cancellation however far the camera stands (the GPU gets it in float as it is).
  f.to_lower_left = -divide(f.horizontal, 2) - divide(f.vertical, 2) - pose.focus_dist * w;
  f.lower_left = f.origin + f.to_lower_left;
  f.lens_u = u;
  f.lens_v = v;
  f.axis_w = w;
  f.lens_radius = pose.aperture / 2;
  f.aspect = aspect_ratio;
  f.fisheye_fov = pose.fisheye_fov * pi / 180;
  f.focus_dist = pose.focus_dist;
  f.projection = uint(pose.projection);
  f.time_open = frame_time + pose.shutter_open;
  f.shutter = (frame_time + pose.shutter_close) - f.time_open;
  f.readout = pose.readout;
  f.image_width = uint(image_width_);
  f.image_height = uint(image_height_);
  if (is_calibrated(pose.projection)) setup_lens(pose, image_width_, image_height_, f);
}

std::optional<glm::dvec2> camera::project(const point3& p) const {
  const vec3 d = p - frame_.origin;
  const glm::dvec3 c(glm::dot(d, frame_.lens_u), -glm::dot(d, frame_.lens_v),
                     -glm::dot(d, frame_.axis_w));
  return project_calibrated(frame_, c);
}

}  // namespace rtvk
