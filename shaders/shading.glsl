// Mirrors host/shading.cpp.
#ifndef RTVK_SHADING_GLSL
#define RTVK_SHADING_GLSL
#include "sphere.glsl"

const float max_float = 3.402823466e+38;  // stands in for the host's infinity as t_max

vec3 sky_color(vec3 d) {
  vec3 unit_direction = unit_vector(d);
  float t = 0.5 * (unit_direction.y + 1.0);
  return (1.0 - t) * vec3(1.0, 1.0, 1.0) + t * vec3(0.5, 0.7, 1.0);
}

vec3 ray_color(ray r) {
  hit_record rec;
  if (hit_world(r, 0.0, max_float, rec)) return 0.5 * (rec.normal + vec3(1.0, 1.0, 1.0));
  return sky_color(r.direction);
}

#endif
