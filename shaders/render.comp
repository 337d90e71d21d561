#version 450
// One invocation per pixel: the lesson's main loop body on the GPU.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

// The host picks the workgroup size from the device's limits (specialization constants 0, 1).
layout(local_size_x_id = 0, local_size_y_id = 1, local_size_z = 1) in;

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block { camera_ubo cam; };
layout(std430, set = 0, binding = RTVK_BINDING_SPHERES) readonly buffer sphere_block {
  gpu_sphere spheres[];
};
layout(std430, set = 0, binding = RTVK_BINDING_IMAGE) writeonly buffer image_block { float rgb[]; };
layout(push_constant) uniform push_block { render_push pc; };

#include "camera.glsl"
#include "shading.glsl"

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;  // x from the left, y from the top
  if (pixel.x >= cam.image_width || pixel.y >= cam.image_height) return;

  uint j = cam.image_height - 1u - pixel.y;  // the lesson counts rows from the bottom
  float u = pixel_coordinate(pixel.x, cam.image_width);
  float v = pixel_coordinate(j, cam.image_height);
  vec3 c = ray_color(get_ray(cam, u, v));

  uint base = 3u * (pixel.y * cam.image_width + pixel.x);
  rgb[base + 0u] = c.r;
  rgb[base + 1u] = c.g;
  rgb[base + 2u] = c.b;
}
