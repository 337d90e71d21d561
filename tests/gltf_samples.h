#pragma once
// The Khronos feature-test models in tests/data/gltf and what their own READMEs call a pass, as
// checks of an image's region colors that both backends' images must meet
// (tests/scene/test_gltf_samples.cpp, tests/gpu/test_gpu_gltf_samples.cpp). Each model is drawn
// unlit (every material flat, so a pixel is the texel, vertex color and emission the file gives
// it, in linear light) from a camera square onto the model's bounds, so that a point of the model
// falls on a pixel the check can name.
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "mesh_file.h"
#include "render_helpers.h"

namespace rtvk::test {

inline const std::filesystem::path gltf_samples = RTVK_TEST_DATA_DIR "/gltf";

// A model's scene drawn unlit, `width` pixels square, 4 samples a pixel, looking at the bounds'
// center along -`toward` (so from the side `toward` points to), `up` up, the bounding sphere
// filling the view. `half` is the half height the view spans at the center, scene units.
struct sample_view {
  scene s;
  point3 center;    // of the bounds, scene units
  double half = 1;  // half the view's height through `center`, scene units
  vec3 right, up;   // the image's directions at `center`, unit
};

inline sample_view sample_scene(const std::string& file, vec3 toward, vec3 up, int width = 128) {
  sample_view v;
  v.s = mesh_scene(gltf_samples / file);
  for (named_material& m : v.s.materials) m.m.type = material_type::flat;
  point3 lo(INFINITY), hi(-INFINITY);
  for (const triangle& t : v.s.triangles)
    for (const point3& p : t.p) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  v.center = 0.5 * (lo + hi);
  v.half = 0.5 * glm::length(hi - lo) * 1.02;
  camera_pose& c = main_camera(v.s).pose;
  c = camera_pose{};
  c.vfov = 30;
  const double distance = v.half / std::tan(0.5 * c.vfov * M_PI / 180);
  c.lookat = v.center;
  c.lookfrom = v.center + distance * glm::normalize(toward);
  c.vup = up;
  c.focus_dist = distance;
  v.right = glm::normalize(glm::cross(up, toward));
  v.up = glm::normalize(glm::cross(glm::normalize(toward), v.right));
  v.s.render.width = width;
  v.s.render.aspect = 1;
  v.s.render.spp = 4;
  return v;
}

// The pixel (column, row) a point of the plane through `center` facing the camera falls on.
inline std::array<int, 2> pixel_of(const sample_view& v, const point3& p) {
  const int w = v.s.render.width;
  const double x = glm::dot(p - v.center, v.right) / v.half,
               y = glm::dot(p - v.center, v.up) / v.half;
  return {int(std::floor(0.5 * w * (1 + x))), int(std::floor(0.5 * w * (1 - y)))};
}

// The direction the camera looks from (unit, from `center` toward the eye).
inline vec3 toward_eye(const sample_view& v) {
  return glm::cross(v.right, v.up);
}

// The pixel (column, row, fractional) any point in front of the camera falls on, in perspective:
// pixel_of for points off the plane through `center`.
inline glm::dvec2 pixel_at(const sample_view& v, const point3& p) {
  const point3 eye = main_camera(v.s).pose.lookfrom;
  const double distance = glm::length(eye - v.center);
  const vec3 from_eye = p - eye;
  const double scale = distance / -glm::dot(from_eye, toward_eye(v)) / v.half;
  const double w = v.s.render.width;
  return {0.5 * w * (1 + glm::dot(from_eye, v.right) * scale),
          0.5 * w * (1 - glm::dot(from_eye, v.up) * scale)};
}

using color_test = std::function<bool(const color&)>;

// Pixels of `fb` within `r` pixels (a square) of (x, y) that pass `test`; the whole image when r <
// 0.
inline int count(const framebuffer& fb, const color_test& test, int x = 0, int y = 0, int r = -1) {
  int n = 0;
  for (int j = 0; j < fb.height(); ++j)
    for (int i = 0; i < fb.width(); ++i)
      if (r < 0 || (std::abs(i - x) <= r && std::abs(j - y) <= r)) n += test(fb.at(i, j));
  return n;
}

// Colors in linear light: one channel (or two) strong, the others near zero.
inline bool strongly_red(const color& c) {
  return c.r > 0.3 && c.g < 0.08 && c.b < 0.08;
}
inline bool strongly_green(const color& c) {
  return c.g > 0.2 && c.r < 0.08 && c.b < 0.08;
}
inline bool strongly_blue(const color& c) {
  return c.b > 0.3 && c.r < 0.08 && c.g < 0.08;
}
inline bool strongly_cyan(const color& c) {
  return c.g > 0.3 && c.b > 0.3 && c.r < 0.08;
}
inline bool strongly_magenta(const color& c) {
  return c.r > 0.3 && c.b > 0.3 && c.g < 0.08;
}
inline bool strongly_yellow(const color& c) {
  return c.r > 0.3 && c.g > 0.3 && c.b < 0.08;
}
inline bool dark(const color& c) {
  return c.r + c.g + c.b < 0.15;
}

// A model, the views its README's pass is seen from, and the check of each view's image: "" when
// it passes, else what is wrong.
struct sample_case {
  std::string name;
  std::vector<sample_view> views;
  std::function<std::string(const sample_view&, const framebuffer&)> check;
};

std::vector<sample_case> sample_cases();  // tests/scene/test_gltf_samples.cpp

// tests/scene/gltf_sample_checks.cpp: OrientationTest's views (one square onto each face of its
// cube) and their check; AlphaModes (tests/data/gltf/AlphaModes, a small stand-in for Khronos'
// AlphaBlendModeTest) and its check.
std::vector<sample_view> orientation_views();
std::string orientation(const sample_view& v, const framebuffer& fb);
sample_view alpha_modes_view();
std::string alpha_modes(const sample_view& v, const framebuffer& fb);

}  // namespace rtvk::test
