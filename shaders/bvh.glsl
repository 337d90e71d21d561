// The slab test of the GPU's binary tree. Where one source cannot serve: the CPU walks a
// four-wide tree with SSE (host/cpu/bvh_world.cpp, host/accel/bvh.h), this shader walks the
// binary tree two children a node in a flat loop; their math is alike (the same safe inverse,
// origin margin and box widening), their order of visits is not. Both test spheres with the shared
// hit_sphere and break ties to the later sphere, so each must find what a plain scan finds:
// Accel.BvhAndThreadsGiveTheIdenticalCpuImage and GpuBook.BvhGivesTheIdenticalGpuImage.
// Reads no buffers; the world's traversal is in world.glsl.
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

// Mirrors child_entries in host/cpu/bvh_world.cpp (ray_box_entry in host/accel/bvh.h, for both
// children at once): where the ray enters each child's box of n grown by `margin` -- x for the
// left child, y for the right -- or -1 to cull. Lanes as in bvh_node: (left min, right min,
// left max, right max).
precise vec2 child_entries(vec3 o, vec3 inv_d, bvh_node n, float t_min, float t_max,
                           float margin) {
  precise vec4 grow = vec4(-margin, -margin, margin, margin);  // mins down, maxes up
  precise vec4 tx = (n.x + grow - o.x) * inv_d.x;
  precise vec4 ty = (n.y + grow - o.y) * inv_d.y;
  precise vec4 tz = (n.z + grow - o.z) * inv_d.z;
  precise vec2 near_x = min(tx.xy, tx.zw), far_x = max(tx.xy, tx.zw);
  precise vec2 near_y = min(ty.xy, ty.zw), far_y = max(ty.xy, ty.zw);
  precise vec2 near_z = min(tz.xy, tz.zw), far_z = max(tz.xy, tz.zw);
  precise vec2 enter = max(max(near_x, near_y), max(near_z, vec2(t_min)));
  precise vec2 leave = min(min(far_x, far_y), min(far_z, vec2(t_max)));
  return vec2(enter.x <= leave.x ? enter.x : -1.0, enter.y <= leave.y ? enter.y : -1.0);
}

#endif
