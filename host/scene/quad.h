#pragma once
#include "hit_quad.h"
#include "vec3.h"

namespace rtvk {

// A quad of the scene (the second book's): the parallelogram with corner Q and edges u and v.
// Plain data; both backends hit it with the shared hit_quad (shaders/shared/hit_quad.h).
struct quad {
  point3 Q{};        // a corner, scene units
  vec3 u{};          // the edge from Q to the next corner, scene units
  vec3 v{};          // the other edge from Q, scene units; the front side is cross(u, v)
  int material = 0;  // index into the scene's materials

  // The book's precomputed plane (normal, D, w), in double.
  quad_geometry geometry() const { return make_quad(Q, u, v); }
};

}  // namespace rtvk
