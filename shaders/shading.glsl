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

// ray_color's loop variables: a path in flight, so the loop can be taken one bounce at a time.
struct path_state {
  ray r;                    // the ray about to be traced
  precise vec3 throughput;  // product of the attenuations so far
  uint depth;               // bounces so far
  random_stream s;          // the path's random numbers (pixel, sample)
};

path_state start_path(ray r, random_stream s) { return path_state(r, vec3(1.0), 0u, s); }

// One trip through ray_color's loop (host/cpu/shading.cpp); render.comp holds the loop itself,
// over all of an invocation's samples, so a lane whose path ended starts its next sample at once.
// Traces p.r and either ends the path, its color in `c`, or scatters it for the next trip. Over
// the loop budget the path ends black and `iterations` tells the caller.
bool ray_color_step(precise inout path_state p, precise out vec3 c, inout uint iterations,
                    inout uint rays) {
  c = vec3(0.0);
  if (++iterations > pc.loop_budget) return true;
  if (p.depth >= pc.max_depth) return true;
  if (p.r.direction == vec3(0.0)) return true;  // the camera gives no ray here: black
  ++rays;
  hit_record rec;
  if (!hit_world(p.r, t_min, max_float, rec, iterations)) {
    if (iterations <= pc.loop_budget) c = p.throughput * sky_color(p.r.direction);
    return true;
  }
  gpu_material m = materials[rec.material];
  if (m.type == RTVK_MATERIAL_NORMAL) {
    c = p.throughput * (0.5 * (rec.normal + vec3(1.0, 1.0, 1.0)));
    return true;
  }
  precise vec3 attenuation;
  precise ray scattered;
  if (!scatter(m, p.r, rec, at_bounce(p.s, p.depth + 1u), attenuation, scattered)) return true;
  p.throughput *= attenuation;
  p.r = scattered;
  ++p.depth;
  return false;
}

#endif
