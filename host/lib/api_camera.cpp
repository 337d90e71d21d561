// The library's cameras made from numbers: a look-at pose, or a calibrated camera as OpenCV and
// COLMAP hold one (a world-to-camera matrix and intrinsics).
#include <algorithm>
#include <cmath>

#include "api_impl.h"
#include "calibration_file.h"
#include "colmap_model.h"
#include "format.h"

namespace rtvk::api {
namespace {

vec3 vec(const std::array<double, 3>& v) {
  return {v[0], v[1], v[2]};
}

// The camera of `pose` drawing exactly width x height pixels.
Camera make(const camera_pose& pose, int width, int height) {
  if (width < 1 || height < 1)
    throw bad_input("camera size " + std::to_string(width) + "x" + std::to_string(height) +
                    ": expected at least 1x1 pixels");
  Camera c;
  c.impl_ = std::make_shared<const Camera::impl>(
      Camera::impl{camera(pose, exact_aspect(width, height), width)});
  return c;
}

}  // namespace

Camera Camera::look_at(const std::array<double, 3>& lookfrom, const std::array<double, 3>& lookat,
                       int width, int height, double vfov, const std::array<double, 3>& vup,
                       double aperture, double focus_dist, const std::string& projection) {
  return translate([&] {
    camera_pose pose;
    pose.lookfrom = vec(lookfrom);
    pose.lookat = vec(lookat);
    pose.vup = vec(vup);
    pose.vfov = vfov;
    pose.aperture = aperture;
    pose.focus_dist = focus_dist;
    const std::optional<rtvk::projection> p = projection_from_name(projection);
    if (!p || is_calibrated(*p))
      throw bad_input("projection " + projection +
                      ": expected perspective, orthographic, equirectangular, "
                      "fisheye-equidistant or fisheye-equisolid (Camera.from_opencv makes the "
                      "calibrated models)");
    pose.projection = *p;
    return make(pose, width, height);
  });
}

namespace {

// OpenCV's camera maps world points p to R p + t and looks down its +z with +y down: its center
// is -R^T t, it looks along R's third row, and its up is minus the second (colmap_pose's rule).
camera_pose opencv_pose(const std::array<double, 16>& m) {
  for (const double x : m)
    if (!std::isfinite(x)) throw bad_input("world_to_camera: a value is not finite");
  const vec3 row_x(m[0], m[1], m[2]), row_y(m[4], m[5], m[6]), row_z(m[8], m[9], m[10]);
  const vec3 t(m[3], m[7], m[11]);
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
    throw bad_input("world_to_camera: the last row must be 0, 0, 0, 1");
  camera_pose pose;
  pose.lookfrom = -(t.x * row_x + t.y * row_y + t.z * row_z);
  pose.lookat = pose.lookfrom + row_z;
  pose.vup = -row_y;
  return pose;
}

}  // namespace

Camera Camera::from_opencv(const std::array<double, 16>& m, double fx, double fy, double cx,
                           double cy, int width, int height, const std::vector<double>& distortion,
                           const std::string& model, double image_circle) {
  return translate([&] {
    camera_pose pose = opencv_pose(m);
    // The calibrated models and how many coefficients each reads.
    const std::optional<rtvk::projection> p = projection_from_name(model);
    if (!p || !is_calibrated(*p))
      throw bad_input("model " + model +
                      ": expected opencv, opencv-fisheye, fisheye-polynomial or cylindrical");
    pose.projection = *p;
    const std::size_t most = *p == projection::opencv           ? 8
                             : *p == projection::opencv_fisheye ? 4
                             : *p == projection::cylindrical    ? 0
                                                                : 5;
    if (distortion.size() > most)
      throw bad_input("distortion: the " + model + " model takes at most " + std::to_string(most) +
                      " coefficients, got " + std::to_string(distortion.size()));
    if (!(image_circle >= 0) || (image_circle > 0 && *p != projection::fisheye_polynomial))
      throw bad_input("image_circle " + format_number(image_circle) +
                      ": a radius >= 0 in pixels, for the fisheye-polynomial model only");
    pose.intrinsics = {width, height, fx, fy, cx, cy, {}, image_circle};
    std::copy(distortion.begin(), distortion.end(), pose.intrinsics.k.begin());
    return make(pose, width, height);
  });
}

Camera Camera::from_opencv_file(const std::array<double, 16>& world_to_camera,
                                const std::string& calibration_file) {
  return translate([&] {
    camera_pose pose = opencv_pose(world_to_camera);
    const calibration cal = read_opencv_calibration(calibration_file);
    pose.projection = cal.model;
    pose.intrinsics = cal.lens;
    return make(pose, cal.lens.width, cal.lens.height);
  });
}

std::vector<std::pair<std::string, Camera>> Camera::from_colmap(
    const std::string& folder, const std::vector<std::string>& names) {
  return translate([&] {
    const std::vector<colmap_view> views = read_colmap_model(folder);
    for (const std::string& n : names)
      if (std::none_of(views.begin(), views.end(),
                       [&](const colmap_view& v) { return v.name == n; }))
        throw bad_input("camera " + n + ": the COLMAP model in " + folder +
                        " has no view of that name");
    std::vector<std::pair<std::string, Camera>> out;
    for (const colmap_view& v : views)
      if (names.empty() || std::find(names.begin(), names.end(), v.name) != names.end())
        out.emplace_back(v.name, make(v.pose, v.pose.intrinsics.width, v.pose.intrinsics.height));
    return out;
  });
}

}  // namespace rtvk::api
