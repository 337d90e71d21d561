#version 450
// Test probe: echoes the camera uniform buffer and the rays get_ray makes for the host's (u, v)
// points, so tests can hold the GPU's view of the camera against the CPU camera.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block { camera_ubo cam; };
layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block { probe_io probe; };

#include "camera.glsl"

void main() {
  probe.echo = cam;
  probe.ray_origin = vec4(get_ray(cam, 0.0, 0.0).origin, 1.0);
  for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
    vec2 uv = probe.uv[k].xy;
    probe.direction[k] = vec4(get_ray(cam, uv.x, uv.y).direction, 0.0);
  }
}
