// Mirrors host/sphere.cpp and host/hittable_list.cpp. Expects `spheres` (gpu_sphere[]) and
// `pc` (render_push) declared by the including shader.
#ifndef RTVK_SPHERE_GLSL
#define RTVK_SPHERE_GLSL
#include "ray.glsl"

bool hit_sphere(gpu_sphere s, ray r, float t_min, float t_max, inout hit_record rec) {
  vec3 oc = r.origin - s.center;
  float a = dot(r.direction, r.direction);
  float half_b = dot(oc, r.direction);
  // As on the host: half_b^2 - a*c without the cancellation that ruins it in float.
  vec3 l = oc - (half_b / a) * r.direction;
  float discriminant = a * (s.radius * s.radius - dot(l, l));
  if (discriminant < 0.0) return false;
  float sqrtd = sqrt(discriminant);

  float root = (-half_b - sqrtd) / a;
  if (root < t_min || t_max < root) {
    root = (-half_b + sqrtd) / a;
    if (root < t_min || t_max < root) return false;
  }
  rec.t = root;
  rec.p = ray_at(r, root);
  set_face_normal(rec, r, divide(rec.p - s.center, s.radius));
  rec.material = s.material;
  float extent = max(max(abs(s.center.x), abs(s.center.y)), abs(s.center.z));
  rec.offset = (extent + s.radius) * (1.0 / 1048576.0);  // 2^-20, as on the host
  return true;
}

// The closest hit over every sphere, as hittable_list::hit. Each iteration counts against the
// loop budget; over budget, the search stops and `iterations` tells the caller.
bool hit_world(ray r, float t_min, float t_max, inout hit_record rec, inout uint iterations) {
  bool hit_anything = false;
  float closest_so_far = t_max;
  for (uint i = 0u; i < pc.sphere_count; ++i) {
    if (++iterations > pc.loop_budget) return false;
    hit_record temp;
    if (hit_sphere(spheres[i], r, t_min, closest_so_far, temp)) {
      hit_anything = true;
      closest_so_far = temp.t;
      rec = temp;
    }
  }
  return hit_anything;
}

#endif
