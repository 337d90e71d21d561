#version 460
// The render with ray queries (--accel rt-query): render_body.glsl, its world searched through the
// driver's acceleration structure (world_rt.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_ray_query : require

layout(local_size_x_id = 0, local_size_y_id = 1, local_size_z = 1) in;
#define RTVK_INVOCATION_ID gl_GlobalInvocationID
#define RTVK_RAY_QUERY
#include "render_body.glsl"
