#include "camera_path.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <stdexcept>
#include <string>

#include "format.h"

namespace rtvk {
namespace {

constexpr double two_pi = 6.283185307179586476925;

// The camera's frame as the camera class builds it: u right, v up, w backwards.
glm::dquat orientation(const camera_pose& p) {
  const vec3 w = unit_vector(p.lookfrom - p.lookat);
  const vec3 u = unit_vector(glm::cross(p.vup, w));
  const vec3 v = glm::cross(w, u);
  return glm::quat_cast(glm::dmat3(u, v, w));
}

// Rodrigues' rotation of `v` by `angle` radians about the unit axis `k`.
vec3 rotate(const vec3& v, const vec3& k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
}

camera_pose orbit_at(const camera_pose& start, double period, double seconds) {
  const double turns = seconds / period;
  if (turns == std::floor(turns)) return start;  // whole turns: exactly the start pose
  camera_pose p = start;
  const double angle = two_pi * (turns - std::floor(turns));
  p.lookfrom = start.lookat + rotate(start.lookfrom - start.lookat, unit_vector(start.vup), angle);
  return p;
}

camera_pose between(const camera_pose& a, const camera_pose& b, double f) {
  const glm::dquat q = glm::slerp(orientation(a), orientation(b), f);  // the short way round
  const glm::dmat3 frame = glm::mat3_cast(glm::normalize(q));
  const double distance =
      glm::mix(glm::length(a.lookfrom - a.lookat), glm::length(b.lookfrom - b.lookat), f);
  camera_pose p;
  p.lookfrom = glm::mix(a.lookfrom, b.lookfrom, f);
  p.lookat = p.lookfrom - frame[2] * distance;
  p.vup = frame[1];  // the interpolated frame's own up: perpendicular to the view, never flips
  p.vfov = glm::mix(a.vfov, b.vfov, f);
  p.aperture = glm::mix(a.aperture, b.aperture, f);
  p.focus_dist = glm::mix(a.focus_dist, b.focus_dist, f);
  p.projection = a.projection;  // a model is not interpolated: the earlier keyframe's holds
  p.fisheye_fov = glm::mix(a.fisheye_fov, b.fisheye_fov, f);
  p.shutter_open = a.shutter_open;  // a shutter is not interpolated either: the earlier one's
  p.shutter_close = a.shutter_close;
  p.readout = a.readout;        // nor a rolling shutter's readout,
  p.intrinsics = a.intrinsics;  // nor a calibration: they belong to the earlier keyframe's model
  return p;
}

}  // namespace

camera_pose camera_path::at(double seconds) const {
  switch (motion) {
    case camera_motion::fixed:
      return pose;
    case camera_motion::orbit:
      return orbit_at(pose, orbit_period, seconds);
    case camera_motion::keyframes:
      break;
  }
  if (seconds <= keyframes.front().time) return keyframes.front().pose;
  for (std::size_t k = 0; k + 1 < keyframes.size(); ++k) {
    const camera_keyframe &a = keyframes[k], &b = keyframes[k + 1];
    if (seconds < b.time) {
      const double f = (seconds - a.time) / (b.time - a.time);
      return f == 0 ? a.pose : between(a.pose, b.pose, f);
    }
  }
  return keyframes.back().pose;
}

void check_camera_path(const camera_path& path) {
  // Any aspect and width will do: only the pose is being checked. A calibration is checked at
  // the size it was made for (at 1x1 an image taller than twice its width was refused as
  // "another aspect ratio").
  auto check_pose = [](const camera_pose& p) {
    const lens_intrinsics& l = p.intrinsics;
    if (is_calibrated(p.projection) && l.width > 0 && l.height > 0)
      camera(p, double(l.width) / l.height, l.width);
    else
      camera(p, 1, 1);
  };
  switch (path.motion) {
    case camera_motion::fixed:
      check_pose(path.pose);
      return;
    case camera_motion::orbit:
      // Turning about the up axis keeps the view's angle to it: every time is as valid as 0.
      check_pose(path.pose);
      if (!(path.orbit_period > 0) || !std::isfinite(path.orbit_period))
        throw std::invalid_argument("orbit period must be finite and > 0 seconds, got " +
                                    format_number(path.orbit_period));
      return;
    case camera_motion::keyframes:
      break;
  }
  if (path.keyframes.empty()) throw std::invalid_argument("a keyframed camera needs keyframes");
  for (std::size_t k = 0; k < path.keyframes.size(); ++k) {
    const double t = path.keyframes[k].time;
    if (!std::isfinite(t))
      throw std::invalid_argument("keyframe " + std::to_string(k) + ": time must be finite");
    if (k > 0 && !(t > path.keyframes[k - 1].time))
      throw std::invalid_argument("keyframe " + std::to_string(k) + ": time " + format_number(t) +
                                  " is not after the previous keyframe's " +
                                  format_number(path.keyframes[k - 1].time));
    try {
      check_pose(path.keyframes[k].pose);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("keyframe " + std::to_string(k) + ": " + e.what());
    }
  }
  // Between two valid keyframes every pose is valid: the frame is a rotation, the distances,
  // fields of view and focus distances are blends of valid ones.
}

bool valid_camera_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name.front() == '.' || name == "all") return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
      return false;
  return true;
}

}  // namespace rtvk
