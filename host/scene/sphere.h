#pragma once
#include "vec3.h"

namespace rtvk {

// A sphere of the scene: plain data. The CPU hits it through hittable_sphere (cpu/), the GPU
// through gpu_sphere; both with the same math, the shared hit_sphere (shaders/shared).
struct sphere {
  sphere() = default;
  sphere(const point3& center, double radius, int material = 0)
      : center(center), radius(radius), material(material) {}

  point3 center{};      // scene units
  double radius = 0.0;  // scene units, > 0
  int material = 0;     // index into the scene's materials
};

}  // namespace rtvk
