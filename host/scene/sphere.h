#pragma once
#include <optional>

#include "hit_sphere.h"
#include "vec3.h"

namespace rtvk {

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
};

// The instants a render's rays may sample, seconds: a BVH bounds every sphere over all of them.
struct time_span {
  double lo = 0;  // earliest
  double hi = 1;  // latest
};

}  // namespace rtvk
