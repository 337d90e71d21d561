// ray_color's loop, a bounce per trip: the steps are the shared kernels' (ray_color.h), which
// the CPU runs too (host/cpu/shading.cpp); what is the GPU's own is the world search (world.glsl)
// and the loop budget. Expects `materials` (gpu_material[]) and `pc` (render_push) declared by
// the including shader.
#ifndef RTVK_SHADING_GLSL
#define RTVK_SHADING_GLSL
#include "ray_color.h"
#include "world.glsl"

const float max_float = 3.402823466e+38;  // stands in for the host's infinity as t_max

// One trip through ray_color's loop; render.comp holds the loop itself, over all of an
// invocation's samples, so a lane whose path ended starts its next sample at once. Traces p.r
// and either ends the path, its color in `c`, or scatters it for the next trip. Over the loop
// budget the path ends black and `iterations` tells the caller.
bool ray_color_step(precise inout path_state p, precise out vec3 c, inout uint iterations,
                    inout uint rays) {
  c = vec3(0.0);
  if (++iterations > pc.loop_budget) return true;
  if (path_ends_unlit(p, pc.max_depth)) return true;
  ++rays;
  hit_record rec;
  if (!hit_world(p.r, t_min, max_float, rec, iterations)) {
    if (iterations <= pc.loop_budget) c = path_missed(p, pc.sky_horizon, pc.sky_zenith);
    return true;
  }
  gpu_material m = materials[rec.material];
  return path_hit(p, rec, m.type, m.albedo, m.fuzz, m.ir, c);
}

#endif
