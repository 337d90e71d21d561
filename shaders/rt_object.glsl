// What rt_object.rint (intersection) and rt_object.rahit (any-hit) share: the scene's buffers,
// the push constants and world.glsl's object tests, for the candidates a ray-tracing pipeline's
// traversal proposes (world_rt.glsl).
#include "shared_types.h"

layout(push_constant) uniform push_block {
  render_push pc;
};
#include "scene_buffers.glsl"
layout(std430, set = 0, binding = RTVK_BINDING_RAY_TIMES) shadercallcoherent readonly buffer
    ray_time_block {
  float ray_times[];
};
const bool use_bvh = true;  // world.glsl's traversal is not compiled here
#define RTVK_RT_OBJECT_STAGE
#include "world.glsl"

// The traced ray in the space of the candidate's group, at the instant it samples.
ray candidate_ray() {
  float time = motion ? ray_times[launch_slot(gl_LaunchIDEXT)] : 0.0;
  return group_ray(gl_InstanceCustomIndexEXT,
                   ray(gl_WorldRayOriginEXT, gl_WorldRayDirectionEXT, time));
}
