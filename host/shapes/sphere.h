#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "hit_sphere.h"
#include "vec3.h"

namespace rtvk {

// The instants a render's rays may sample, seconds: a BVH bounds every sphere over all of them.
struct time_span {
  double lo = 0;  // earliest
  double hi = 1;  // latest
};

// A sphere of the scene: plain data. The CPU hits it through hittable_sphere (cpu/), the GPU
// through gpu_sphere; both with the same math, the shared hit_sphere (shaders/shared).
struct sphere {
  sphere() = default;
  sphere(const point3& center, double radius, int material = 0,
         std::optional<point3> center1 = std::nullopt)
      : center(center), radius(radius), material(material), center1(center1) {}

  point3 center{};                // at time 0, scene units
  double radius = 0.0;            // scene units, > 0
  int material = 0;               // index into the scene's materials
  std::optional<point3> center1;  // at time 1, scene units, for a sphere that moves
  bool sampled = false;           // lights sampling aims at it though it emits nothing (the
                                  // third book's glass sphere); a lamp is aimed at anyway

  // Scene units per second: center1 - center, or zero.
  vec3 velocity() const { return center1 ? *center1 - center : vec3(0); }
  // Where the center is at `time` (seconds): linear, before 0 and after 1 too. A sphere without
  // center1 is exactly at `center`.
  point3 center_at(double time) const {
    return center1 ? moved_center(center, velocity(), time) : center;
  }
  // Corners lo and hi of its box over the whole of `motion`. The GPU moves a center in float
  // (float(c) + float(t) * float(v): a few roundings of 2^-24 each, relative), so a moving
  // sphere's box grows by sixteen times that bound.
  std::array<point3, 2> bounds(time_span motion = {}) const {
    const vec3 r(std::abs(radius));
    const point3 a = center_at(motion.lo), b = center_at(motion.hi);
    vec3 slack(0);
    if (center1) {
      const double t = std::max(std::abs(motion.lo), std::abs(motion.hi));
      slack = (glm::abs(center) + t * glm::abs(velocity())) * 0x1p-20;
    }
    return {glm::min(a, b) - r - slack, glm::max(a, b) + r + slack};
  }
};

}  // namespace rtvk
