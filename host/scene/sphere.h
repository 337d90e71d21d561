#pragma once
#include "vec3.h"

namespace rtvk {

// A sphere of the scene: plain data. The CPU hits it through hittable_sphere (cpu/), the GPU
// through gpu_sphere; both with the same math, the shared hit_sphere (shaders/shared).
struct sphere {
  sphere() = default;
  sphere(const point3& center, double radius, int material = 0, const vec3& velocity = {})
      : center(center), radius(radius), material(material), velocity(velocity) {}

  point3 center{};      // at time 0, scene units
  double radius = 0.0;  // scene units, > 0
  int material = 0;     // index into the scene's materials
  vec3 velocity{};      // center at time 1 minus center at time 0: scene units per second

  // Where the center is at `time` (seconds): linear, before 0 and after 1 too. A sphere that
  // does not move is exactly at `center` (0 * time adds nothing).
  point3 center_at(double time) const { return center + time * velocity; }
};

// The instants a render's rays may sample, seconds: a BVH bounds every sphere over all of them.
struct time_span {
  double lo = 0;  // earliest
  double hi = 1;  // latest
};

}  // namespace rtvk
