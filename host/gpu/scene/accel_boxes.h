#pragma once
// The boxes the driver's bottom levels hold for the shapes it knows only by their boxes
// (spheres, quads, disks: scene_accel.cpp), from the packed arrays the shaders read.
#include <algorithm>
#include <cmath>

#include <volk.h>
#include <glm/common.hpp>

#include "shared_types.h"
#include "sphere.h"

namespace rtvk::gpu {

// How far past an object its box reaches: the driver tests the ray in an instance's space with
// its own inverse of the placement, which may round differently from frame_of's, and a box
// must never be missed where test_object would hit (a candidate too many costs a test only).
inline float box_margin(const glm::vec3& lo, const glm::vec3& hi) {
  const float most = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x),
                               std::abs(hi.y), std::abs(hi.z)});
  return most * (1.0f / 65536.0f) + 1e-6f;
}

inline VkAabbPositionsKHR box(glm::vec3 lo, glm::vec3 hi) {
  const float m = box_margin(lo, hi);
  return {lo.x - m, lo.y - m, lo.z - m, hi.x + m, hi.y + m, hi.z + m};
}

// A sphere's box over the motion span (it moves in a straight line: its ends bound it).
inline VkAabbPositionsKHR sphere_box(const gpu_sphere& s, const glm::vec3& velocity,
                                     time_span motion) {
  const float r = std::abs(s.radius);
  const glm::vec3 a = s.center + float(motion.lo) * velocity;
  const glm::vec3 b = s.center + float(motion.hi) * velocity;
  return box(glm::min(a, b) - r, glm::max(a, b) + r);
}

// A disk's box: along axis k it reaches radius * sqrt(1 - n_k^2) from its center.
inline VkAabbPositionsKHR disk_box(const gpu_disk& d) {
  const glm::vec3 reach = d.radius * glm::sqrt(glm::max(1.0f - d.normal * d.normal, 0.0f));
  return box(d.center - reach, d.center + reach);
}

inline VkAabbPositionsKHR quad_box(const gpu_quad& q) {
  const glm::vec3 c[] = {q.Q, q.Q + q.u, q.Q + q.v, q.Q + q.u + q.v};
  glm::vec3 lo = c[0], hi = c[0];
  for (const glm::vec3& p : c) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return box(lo, hi);
}

}  // namespace rtvk::gpu
