// Two more feature-test checks for tests/gltf_samples.h's cases: OrientationTest (its arrows point
// at their targets) and AlphaModes (OPAQUE, BLEND and MASK at three cutoffs, over a blue quad).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "gltf_samples.h"

namespace rtvk {
namespace test {
namespace {

// OrientationTest's targets, read from the .glb's own vertex data: the README says they are
// baked there (their nodes have no transform), so where they lie owes nothing to the node
// transforms under test, which place only the arrows.
struct orientation_target {
  std::string name;            // the node's, "TargetX1" ...
  glm::dvec3 hue;              // the material's base color factor (arrow and target share it)
  std::vector<point3> points;  // the mesh's vertices, scene units
};

struct orientation_file {
  double cube_half = 0;  // the base cube's half size (its POSITION max x), scene units
  std::vector<orientation_target> targets;
};

orientation_file read_orientation_file() {
  std::ifstream in(gltf_samples / "OrientationTest/OrientationTest.glb", std::ios::binary);
  const std::string glb{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto u32 = [&](std::size_t at) {
    std::uint32_t x = 0;
    std::memcpy(&x, glb.data() + at, 4);
    return std::size_t(x);
  };
  const std::size_t json_size = u32(12);
  const nlohmann::json j = nlohmann::json::parse(glb.substr(20, json_size));
  const char* bin = glb.data() + 20 + json_size + 8;
  const auto positions = [&](const nlohmann::json& mesh) {
    const nlohmann::json& a =
        j["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
    const nlohmann::json& view = j["bufferViews"][a["bufferView"].get<int>()];
    const std::size_t at = view.value("byteOffset", 0) + a.value("byteOffset", 0);
    std::vector<point3> out(a["count"].get<std::size_t>());
    for (std::size_t k = 0; k < out.size(); ++k) {
      float p[3];
      std::memcpy(p, bin + at + 12 * k, 12);  // tightly packed float VEC3 (no byteStride here)
      out[k] = point3(p[0], p[1], p[2]);
    }
    return out;
  };
  orientation_file f;
  for (const nlohmann::json& n : j["nodes"]) {
    const std::string name = n["name"];
    const nlohmann::json& mesh = j["meshes"][n["mesh"].get<int>()];
    if (name == "BaseCube")
      f.cube_half =
          j["accessors"][mesh["primitives"][0]["attributes"]["POSITION"].get<int>()]["max"][0];
    if (name.rfind("Target", 0) != 0) continue;
    for (const char* key : {"matrix", "rotation", "translation", "scale", "children"})
      if (n.contains(key))  // then its vertices are not where it is drawn
        throw std::runtime_error(name + " has a " + key + ": its place is not baked");
    const auto factor = j["materials"][mesh["primitives"][0]["material"].get<int>()]
                         ["pbrMetallicRoughness"]["baseColorFactor"];
    f.targets.push_back({name, glm::dvec3(factor[0], factor[1], factor[2]), positions(mesh)});
  }
  return f;
}

// The arrows' colors are primaries and their mixes at 0.8 (the cube is a light blue of all three).
color_test hue_of(glm::dvec3 hue) {
  return [hue](const color& c) {
    for (int k = 0; k < 3; ++k)
      if (hue[k] > 0.5 ? c[k] < 0.3 : c[k] > 0.08) return false;
    return true;
  };
}

// One face's arrow, seen square on: its pixels (those of its color on the face, less the target's
// projected box grown by a pixel) lie along a line through the target's center, and reach the
// target: the tip touches it. A rotation turned the wrong way (a transposed matrix) swings the
// arrow 20 to 140 degrees off the target (the README's failure image).
std::string arrow_check(const sample_view& v, const framebuffer& fb, const orientation_target& t,
                        double cube_half) {
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (const point3& p : t.points) {
    lo = glm::min(lo, pixel_at(v, p));
    hi = glm::max(hi, pixel_at(v, p));
  }
  const glm::dvec2 target = 0.5 * (lo + hi);
  const glm::dvec2 face = pixel_at(v, v.center + cube_half * (toward_eye(v) + v.right + v.up));
  const double face_half = face.x - 0.5 * fb.width() - 2;  // less 2 pixels of edge
  const color_test same = hue_of(t.hue);
  std::vector<glm::dvec2> arrow;
  double gap = INFINITY;  // from the arrow's pixels to the target's box, pixels
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      if (std::abs(p.x - 0.5 * fb.width()) > face_half ||
          std::abs(p.y - 0.5 * fb.height()) > face_half || !same(fb.at(x, y)))
        continue;
      const glm::dvec2 out = glm::max(glm::max(lo - 1.0 - p, p - hi - 1.0), glm::dvec2(0));
      if (out == glm::dvec2(0)) continue;  // the target's
      arrow.push_back(p);
      gap = std::min(gap, glm::length(out));
    }
  if (arrow.size() < 100)
    return t.name + "'s arrow: " + std::to_string(arrow.size()) + " pixels, want >= 100; ";
  glm::dvec2 mean(0);
  for (const glm::dvec2& p : arrow) mean += p / double(arrow.size());
  double xx = 0, yy = 0, xy = 0;
  for (const glm::dvec2& p : arrow) {
    xx += (p.x - mean.x) * (p.x - mean.x);
    yy += (p.y - mean.y) * (p.y - mean.y);
    xy += (p.x - mean.x) * (p.y - mean.y);
  }
  const double axis = 0.5 * std::atan2(2 * xy, xx - yy);  // the pixels' principal direction
  const glm::dvec2 to_target = glm::normalize(target - mean);
  const double off = std::acos(std::min(1.0, std::abs(std::cos(axis) * to_target.x +
                                                      std::sin(axis) * to_target.y))) *
                     180 / M_PI;
  std::string out;
  if (off > 5)
    out += t.name + "'s arrow: its axis passes " + std::to_string(off) +
           " degrees off the target, want <= 5; ";
  if (gap > 3)
    out += t.name + "'s arrow: its tip " + std::to_string(gap) +
           " pixels from the target, want <= 3; ";
  return out;
}

}  // namespace

std::vector<sample_view> orientation_views() {
  const vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  std::vector<sample_view> out;
  for (const auto& [toward, up] : {std::pair(x, y), std::pair(-x, y), std::pair(y, z),
                                   std::pair(-y, z), std::pair(z, y), std::pair(-z, y)})
    out.push_back(sample_scene("OrientationTest/OrientationTest.glb", toward, up, 160));
  return out;
}

// OrientationTest: on each face of the cube, the arrow of each color points at the target of its
// color (red, green, blue: quaternions about X, Y, Z; cyan, magenta, yellow: matrices).
std::string orientation(const sample_view& v, const framebuffer& fb) {
  static const orientation_file file = read_orientation_file();
  std::string out;
  int seen = 0;
  for (const orientation_target& t : file.targets) {
    glm::dvec3 center(0);
    for (const point3& p : t.points) center += p / double(t.points.size());
    if (glm::dot(center - v.center, toward_eye(v)) < 0.8 * file.cube_half)
      continue;  // not this face's
    ++seen;
    out += arrow_check(v, fb, t, file.cube_half);
  }
  return seen == 1 ? out : out + std::to_string(seen) + " targets on this face, want 1; ";
}

// AlphaModes (tests/data/gltf/AlphaModes/make_alpha_modes.py made it): five quads 2 wide and
// 0.4 tall at z = 0, 0.1 apart, the top one's top edge at y = 1.2, each textured with one row of
// 8 white texels of these alpha bytes; behind them a blue quad.
namespace {
constexpr int ramp_alpha[8] = {0, 63, 64, 127, 128, 191, 192, 255};
constexpr double quad_width = 2, quad_height = 0.4, quad_gap = 0.1, quads_top = 1.2;

bool white(const color& c) {
  return c.r > 0.999 && c.g > 0.999 && c.b > 0.999;
}
bool blue(const color& c) {
  return c.r < 0.001 && c.g < 0.001 && c.b > 0.999;
}

// The pixels of quad `row` (0 at the top), texel `column`, at least 2 pixels inside its edges.
std::vector<color> texel_pixels(const sample_view& v, const framebuffer& fb, int row, int column) {
  const double x0 = -0.5 * quad_width + column * quad_width / 8,
               y1 = quads_top - row * (quad_height + quad_gap);
  const glm::dvec2 a = pixel_at(v, point3(x0, y1, 0)),
                   b = pixel_at(v, point3(x0 + quad_width / 8, y1 - quad_height, 0));
  std::vector<color> out;
  for (int y = int(std::ceil(a.y + 2)); y + 1 <= b.y - 2; ++y)
    for (int x = int(std::ceil(a.x + 2)); x + 1 <= b.x - 2; ++x) out.push_back(fb.at(x, y));
  return out;
}

std::string mismatches(int n, const std::string& what) {
  return n == 0 ? "" : what + ": " + std::to_string(n) + " pixels; ";
}

// MASK at `cutoff`: a texel whose alpha is at least the cutoff is all white, any other all blue
// (the ray passes): no blending, and exactly the texels >= cutoff (each cutoff has a texel a byte
// below and one a byte above it).
std::string mask_check(const sample_view& v, const framebuffer& fb, int row, double cutoff) {
  std::string out;
  for (int k = 0; k < 8; ++k) {
    const bool shown = ramp_alpha[k] / 255.0 >= cutoff;
    int wrong = 0;
    for (const color& c : texel_pixels(v, fb, row, k)) wrong += !(shown ? white(c) : blue(c));
    out +=
        mismatches(wrong, "MASK " + std::to_string(cutoff) + ", alpha " +
                              std::to_string(ramp_alpha[k]) + (shown ? " not white" : " not blue"));
  }
  return out;
}

// BLEND: each sample of a pixel is white with probability alpha (stochastic transparency), else
// the blue behind, so a texel's mean red is alpha; over n samples its standard deviation is
// sqrt(alpha (1 - alpha) / n). Held to 5 of them (a chance of about 6e-7 a texel to fail a correct
// renderer), and 0.01 beside (the float texel).
std::string blend_check(const sample_view& v, const framebuffer& fb, int row) {
  std::string out;
  for (int k = 0; k < 8; ++k) {
    const std::vector<color> pixels = texel_pixels(v, fb, row, k);
    const double alpha = ramp_alpha[k] / 255.0, n = double(pixels.size()) * v.s.render.spp;
    double red = 0;
    int not_mix = 0;  // pixels off the line from blue to white
    for (const color& c : pixels) {
      red += c.r / double(pixels.size());
      not_mix += std::abs(c.r - c.g) > 1e-4 || c.b < 0.999;
    }
    const double tolerance = 5 * std::sqrt(alpha * (1 - alpha) / n) + 0.01;
    if (pixels.size() < 50 || std::abs(red - alpha) > tolerance || not_mix > 0)
      out += "BLEND, alpha " + std::to_string(ramp_alpha[k]) + ": mean red " + std::to_string(red) +
             " over " + std::to_string(pixels.size()) + " pixels (" + std::to_string(not_mix) +
             " not a mix of white and blue), want " + std::to_string(alpha) + " +- " +
             std::to_string(tolerance) + "; ";
  }
  return out;
}
}  // namespace

sample_view alpha_modes_view() {
  sample_view v = sample_scene("AlphaModes/AlphaModes.gltf", vec3(0, 0, 1), vec3(0, 1, 0), 160);
  v.s.render.spp = 16;
  return v;
}

// AlphaModes, from the top: OPAQUE ignores alpha (all white, the blue behind never seen), BLEND
// mixes white over blue by alpha, MASK shows the texels at or above 0.5 (glTF's default cutoff:
// the file gives none), 0.25 and 0.75.
std::string alpha_modes(const sample_view& v, const framebuffer& fb) {
  int not_white = 0;
  for (int k = 0; k < 8; ++k)
    for (const color& c : texel_pixels(v, fb, 0, k)) not_white += !white(c);
  return mismatches(not_white, "OPAQUE not white") + blend_check(v, fb, 1) +
         mask_check(v, fb, 2, 0.5) + mask_check(v, fb, 3, 0.25) + mask_check(v, fb, 4, 0.75);
}

}  // namespace test
}  // namespace rtvk
