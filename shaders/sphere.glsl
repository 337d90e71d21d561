// Mirrors host/cpu/hittable_sphere.cpp, and the slab test of host/accel/bvh.h. Reads no buffers:
// probes include it alone; the world's traversal is in world.glsl.
#ifndef RTVK_SPHERE_GLSL
#define RTVK_SPHERE_GLSL
#include "ray.glsl"

// Mirrors hit_distance(sphere, ...) in host/cpu/hittable_sphere.cpp: the nearest root in
// [t_min, t_max], if any.
bool hit_distance(gpu_sphere s, ray r, float t_min, float t_max, precise out float t) {
  t = 0.0;
  precise vec3 oc = r.origin - s.center;
  precise float a = dot3(r.direction, r.direction);
  precise float half_b = dot3(oc, r.direction);
  // As on the host: half_b^2 - a*c without the cancellation that ruins it in float.
  precise vec3 l = oc - (half_b / a) * r.direction;
  precise float discriminant = a * (s.radius * s.radius - dot3(l, l));
  if (discriminant < 0.0) return false;
  precise float sqrtd = sqrt(discriminant);

  // As on the host: only a finite root inside the interval is a hit (NaN fails every comparison).
  precise float root = (-half_b - sqrtd) / a;
  if (!(t_min <= root && root <= t_max && !isinf(root))) {
    root = (-half_b + sqrtd) / a;
    if (!(t_min <= root && root <= t_max && !isinf(root))) return false;
  }
  t = root;
  return true;
}

// Mirrors record_hit(sphere, ...).
void record_hit(gpu_sphere s, ray r, float t, precise inout hit_record rec) {
  rec.t = t;
  rec.p = ray_at(r, t);
  precise vec3 outward_normal = divide(rec.p - s.center, s.radius);
  set_face_normal(rec, r, outward_normal);
  rec.material = s.material;
  precise float extent = max(max(abs(s.center.x), abs(s.center.y)), abs(s.center.z));
  rec.offset = (extent + s.radius) * (1.0 / 1048576.0);  // 2^-20, as on the host
}

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
