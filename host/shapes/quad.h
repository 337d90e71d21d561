#pragma once
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "hit_quad.h"
#include "vec3.h"

namespace rtvk {

// A quad of the scene (the second book's): the parallelogram with corner Q and edges u and v.
// Plain data; both backends hit it with the shared hit_quad (shaders/shared/hit_quad.h).
struct quad {
  point3 Q{};            // a corner, scene units
  vec3 u{};              // the edge from Q to the next corner, scene units
  vec3 v{};              // the other edge from Q, scene units; the front side is cross(u, v)
  int material = 0;      // index into the scene's materials
  bool sampled = false;  // lights sampling aims at it though it emits nothing (as sphere's)

  // The book's precomputed plane (normal, D, w), in double.
  quad_geometry geometry() const { return make_quad(Q, u, v); }
  // Corners lo and hi of its box: the four corners' extremes.
  std::array<point3, 2> bounds() const {
    const point3 c[] = {Q, Q + u, Q + v, Q + u + v};
    point3 lo = c[0], hi = c[0];
    for (const point3& p : c) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    return {lo, hi};
  }
};

// Whether edges u and v span an area, in double (the CPU) and in float (the GPU): a quad without
// one has no plane, and its normal would be 0 / 0.
inline bool spans_area(const vec3& u, const vec3& v) {
  const vec3 n = glm::cross(u, v);
  const glm::vec3 nf = glm::cross(glm::vec3(u), glm::vec3(v));
  const double len2 = glm::dot(n, n);
  const float len2f = glm::dot(nf, nf);
  return len2 > 0 && std::isfinite(len2) && len2f > 0 && std::isfinite(len2f);
}

}  // namespace rtvk
