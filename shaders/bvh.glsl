// The slab test of the four-wide tree, which the CPU walks too (host/accel/wide_bvh.h): the CPU
// tests a node's four boxes with SSE (host/cpu/bvh_world.cpp), this shader with four-lane
// vectors; their math is alike (the same safe inverse, origin margin and box widening). Both test
// spheres with the shared hit_sphere and break ties to the later sphere, so each must find what a
// plain scan finds: Accel.BvhAndThreadsGiveTheIdenticalCpuImage and
// GpuBook.BvhGivesTheIdenticalGpuImage. Reads no buffers; the world's traversal is in world.glsl.
#ifndef RTVK_BVH_GLSL
#define RTVK_BVH_GLSL
#include "ray.h"

// Mirrors safe_inverse in host/accel/bvh.h: no zero components, so no 0 * infinity in the slab
// test.
precise vec3 safe_inverse(vec3 d) {
  precise vec3 c = vec3(abs(d.x) < 1e-20 ? (d.x < 0.0 ? -1e-20 : 1e-20) : d.x,
                abs(d.y) < 1e-20 ? (d.y < 0.0 ? -1e-20 : 1e-20) : d.y,
                abs(d.z) < 1e-20 ? (d.z < 0.0 ? -1e-20 : 1e-20) : d.z);
  return 1.0 / c;
}

// Mirrors origin_margin in host/accel/bvh.h: how far float rounding can misplace a ray from o.
precise float origin_margin(vec3 o) {
  return max(max(abs(o.x), abs(o.y)), abs(o.z)) * (1.0 / 1048576.0);
}

// The four-wide node's children (host/cpu/bvh_world.cpp's child_entries, four lanes at once):
// where the ray enters each child's box grown by `margin` (in `enter`), and a bit per child it
// enters before t_max (within the lanes in use).
uint wide_entries(vec3 o, vec3 inv_d, bvh_wide_node n, float t_min, float t_max, float margin,
                  precise out vec4 enter) {
  precise vec4 x0 = (n.lo_x - margin - o.x) * inv_d.x, x1 = (n.hi_x + margin - o.x) * inv_d.x;
  precise vec4 y0 = (n.lo_y - margin - o.y) * inv_d.y, y1 = (n.hi_y + margin - o.y) * inv_d.y;
  precise vec4 z0 = (n.lo_z - margin - o.z) * inv_d.z, z1 = (n.hi_z + margin - o.z) * inv_d.z;
  enter = max(max(min(x0, x1), min(y0, y1)), max(min(z0, z1), vec4(t_min)));
  precise vec4 leave = min(min(max(x0, x1), max(y0, y1)), min(max(z0, z1), vec4(t_max)));
  bvec4 in_box = lessThanEqual(enter, leave);
  uint bits = (in_box.x ? 1u : 0u) | (in_box.y ? 2u : 0u) | (in_box.z ? 4u : 0u) |
              (in_box.w ? 8u : 0u);
  return bits & n.lanes;
}

#endif
