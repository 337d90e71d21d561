#version 450
// The render on the compute BVH (--accel bvh and none): render_body.glsl.
#extension GL_GOOGLE_include_directive : require

// The host picks the workgroup size from the device's limits (specialization constants 0, 1).
layout(local_size_x_id = 0, local_size_y_id = 1, local_size_z = 1) in;
#define RTVK_INVOCATION_ID gl_GlobalInvocationID
#include "render_body.glsl"
