#include "colmap_views.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "errors.h"

namespace rtvk {
namespace {

// COLMAP's SIMPLE_RADIAL and RADIAL are OpenCV's k1 (and k2) with p1 = p2 = 0; OPENCV and
// FULL_OPENCV are OpenCV's k1 k2 p1 p2 [k3 k4 k5 k6]; OPENCV_FISHEYE is OpenCV's fisheye. The
// ids are COLMAP's (src/base/camera_models.h).
constexpr colmap_camera_model camera_models[] = {
    {"SIMPLE_PINHOLE", 0, projection::opencv, "f cx cy", {focal, center_x, center_y}, 3},
    {"PINHOLE", 1, projection::opencv, "fx fy cx cy", {focal_x, focal_y, center_x, center_y}, 4},
    {"SIMPLE_RADIAL", 2, projection::opencv, "f cx cy k", {focal, center_x, center_y, 0}, 4},
    {"RADIAL", 3, projection::opencv, "f cx cy k1 k2", {focal, center_x, center_y, 0, 1}, 5},
    {"OPENCV",
     4,
     projection::opencv,
     "fx fy cx cy k1 k2 p1 p2",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3},
     8},
    {"FULL_OPENCV",
     6,
     projection::opencv,
     "fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3, 4, 5, 6, 7},
     12},
    {"OPENCV_FISHEYE",
     5,
     projection::opencv_fisheye,
     "fx fy cx cy k1 k2 k3 k4",
     {focal_x, focal_y, center_x, center_y, 0, 1, 2, 3},
     8},
};

// How many parameters COLMAP 3.8 writes for each model id, 0 to 10: FOV (7),
// SIMPLE_RADIAL_FISHEYE, RADIAL_FISHEYE and THIN_PRISM_FISHEYE (10) are not rendered.
constexpr int param_counts[] = {3, 4, 4, 5, 8, 8, 12, 5, 4, 5, 12};

// "cam0/IMG 1.jpg" -> "cam0_IMG_1" (see colmap_model.h), before it is made unique.
std::string base_name(std::string_view image_name) {
  const std::size_t folder = image_name.find_last_of("/\\");
  const std::size_t file_start = folder == std::string_view::npos ? 0 : folder + 1;
  const std::size_t dot = image_name.rfind('.');
  if (dot != std::string_view::npos && dot > file_start) image_name = image_name.substr(0, dot);
  std::string out;
  for (char c : image_name.substr(0, 64)) {
    const bool keep =
        std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
    out += keep ? c : '_';
  }
  if (!out.empty() && out[0] == '.') out[0] = '_';
  if (out.empty()) return "image";
  if (out == "all") return "all_";
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

const colmap_camera_model* colmap_model_named(std::string_view name) {
  for (const colmap_camera_model& m : camera_models)
    if (m.name == name) return &m;
  return nullptr;
}

const colmap_camera_model* colmap_model_numbered(std::int64_t id, int& count) {
  count = id >= 0 && id < std::int64_t(std::size(param_counts)) ? param_counts[id] : -1;
  for (const colmap_camera_model& m : camera_models)
    if (m.id == id) return &m;
  return nullptr;
}

std::string colmap_supported_models() {
  std::string out;
  for (const colmap_camera_model& m : camera_models)
    out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

bool put_colmap_param(const colmap_camera_model& m, int index, double x, lens_intrinsics& lens) {
  const int s = m.slot[std::size_t(index)];
  if ((s == focal || s == focal_x || s == focal_y) && !(x > 0)) return false;
  if (s == focal || s == focal_x) lens.fx = x;
  if (s == focal || s == focal_y) lens.fy = x;
  // COLMAP's (0, 0) is the image's top-left corner, rtvk's (and OpenCV's) the center of the
  // first pixel, half a pixel right of and below that corner.
  if (s == center_x) lens.cx = x - 0.5;
  if (s == center_y) lens.cy = x - 0.5;
  if (s >= 0) lens.k[std::size_t(s)] = x;
  return true;
}

// Its axes in the world are R's rows, x right, y down, z forward (OpenCV's frame); rtvk's camera
// then gets u = x, v = -y, w = -z.
camera_pose colmap_pose(std::array<double, 4> q, const vec3& t, const std::string& where) {
  // Scaled before it is squared, so that neither tiny nor huge numbers lose the rotation.
  const double largest = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
  if (largest == 0) throw usage_error(where + ": the rotation quaternion is zero");
  for (double& c : q) c /= largest;
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double w = q[0] / norm, x = q[1] / norm, y = q[2] / norm, z = q[3] / norm;
  const vec3 row_x(1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y));
  const vec3 row_y(2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x));
  const vec3 row_z(2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y));
  // -R^T t: the rows weighted by t's components.
  const point3 center = -(t.x * row_x + t.y * row_y + t.z * row_z);
  if (!std::isfinite(center.x) || !std::isfinite(center.y) || !std::isfinite(center.z))
    throw usage_error(where + ": the camera's center -R^T t is not finite");
  camera_pose pose;
  pose.lookfrom = center;
  pose.lookat = center + row_z;
  pose.vup = -row_y;
  // So far from the origin that a unit step is rounded away, the view direction would be lost.
  if (glm::length((pose.lookat - pose.lookfrom) - row_z) > 1e-6)
    throw usage_error(where +
                      ": the camera's center is too far from the origin to keep its direction");
  return pose;
}

std::string colmap_names::take(std::string_view image_name) {
  const std::string base = base_name(image_name);
  if (used_.insert(lower(base)).second) return base;
  int& n = next_[lower(base)];  // each base's counter only moves forward: linear overall
  for (n = std::max(n, 2);; ++n) {
    const std::string suffix = "-" + std::to_string(n);
    const std::string name = base.substr(0, 64 - suffix.size()) + suffix;
    if (used_.insert(lower(name)).second) return name;
  }
}

}  // namespace rtvk
