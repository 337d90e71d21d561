// Mirrors host/cpu/shading.cpp.
#ifndef RTVK_SHADING_GLSL
#define RTVK_SHADING_GLSL
#include "material.glsl"
#include "world.glsl"

const float max_float = 3.402823466e+38;  // stands in for the host's infinity as t_max
const float t_min = 0.001;                // ignore self-hits ("shadow acne")

precise vec3 sky_color(vec3 d) {
  precise vec3 unit_direction = unit_vector(d);
  precise float t = 0.5 * (unit_direction.y + 1.0);
  return (1.0 - t) * pc.sky_horizon + t * pc.sky_zenith;
}

precise vec3 ray_color(ray r, random_stream s, inout uint iterations, inout uint rays) {
  precise vec3 throughput = vec3(1.0, 1.0, 1.0);
  for (uint depth = 0u; depth < pc.max_depth; ++depth) {
    if (++iterations > pc.loop_budget) return vec3(0.0);
    ++rays;
    hit_record rec;
    if (!hit_world(r, t_min, max_float, rec, iterations)) {
      if (iterations > pc.loop_budget) return vec3(0.0);
      return throughput * sky_color(r.direction);
    }
    gpu_material m = materials[rec.material];
    if (m.type == RTVK_MATERIAL_NORMAL) return throughput * (0.5 * (rec.normal + vec3(1.0, 1.0, 1.0)));
    precise vec3 attenuation;
    precise ray scattered;
    if (!scatter(m, r, rec, at_bounce(s, depth + 1u), attenuation, scattered)) return vec3(0.0);
    throughput *= attenuation;
    r = scattered;
  }
  return vec3(0.0);
}

#endif
