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

// Mirrors ray_box_entry in host/accel/bvh.h: the entry distance into the box grown by `margin`,
// or -1 to cull.
precise float ray_box_entry(vec3 o, vec3 inv_d, bvh_node n, float t_min, float t_max,
                            float margin) {
  precise vec3 t0 = (n.bounds_min - margin - o) * inv_d;
  precise vec3 t1 = (n.bounds_max + margin - o) * inv_d;
  precise vec3 near = min(t0, t1);
  precise vec3 far = max(t0, t1);
  precise float enter = max(max(near.x, near.y), max(near.z, t_min));
  precise float leave = min(min(far.x, far.y), min(far.z, t_max));
  return enter <= leave ? enter : -1.0;
}

#endif
