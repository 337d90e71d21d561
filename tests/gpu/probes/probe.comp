#version 450
// Test probe: the rays get_ray makes for the host's (u, v) and lens points, so tests can hold the
// GPU's camera against the CPU camera. (The structs' layout is checked from the SPIR-V itself.)
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block { camera_ubo cam; };
layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block { probe_io probe; };

const bool calibrated_cameras = true;  // camera_rays.h: every camera model
#include "camera_rays.h"

void main() {
  for (int k = 0; k < RTVK_PROBE_POINTS; ++k) {
    vec4 uv = probe.uv[k];
    ray r = get_ray(cam, uv.x, uv.y, uv.zw);
    probe.direction[k] = vec4(r.direction, 0.0);
    probe.ray_origin[k] = vec4(r.origin, 1.0);
  }
}
