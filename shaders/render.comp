#version 450
// One invocation per pixel and view draws one sample (pc.sample_index) and adds it to the pixel's
// sum; the host dispatches once per sample, so no invocation comes near lavapipe's loop cap.
// The dispatch's z index is the view: every camera (or animation frame) of a group shares the
// scene buffers and the dispatch.
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

// The host picks the workgroup size from the device's limits (specialization constants 0, 1), and
// fixes the render's switches when it builds the pipeline (2 to 5), so the compiler drops the
// code a render does not use instead of branching on it in every invocation.
layout(local_size_x_id = 0, local_size_y_id = 1, local_size_z = 1) in;
layout(constant_id = RTVK_SPEC_JITTER) const bool jitter = false;  // random spots in the pixel
layout(constant_id = RTVK_SPEC_LENS) const bool any_lens = false;  // a view has an aperture
layout(constant_id = RTVK_SPEC_USE_BVH) const bool use_bvh = true;  // else every sphere in turn
layout(constant_id = RTVK_SPEC_COUNT_RAYS) const bool count_rays = false;  // per-pixel counts

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block {
  camera_ubo cams[RTVK_MAX_VIEWS];
};
layout(std430, set = 0, binding = RTVK_BINDING_SPHERES) readonly buffer sphere_block {
  gpu_sphere spheres[];
};
layout(std430, set = 0, binding = RTVK_BINDING_MATERIALS) readonly buffer material_block {
  gpu_material materials[];
};
layout(std430, set = 0, binding = RTVK_BINDING_IMAGE) buffer image_block { float rgb[]; };
layout(std430, set = 0, binding = RTVK_BINDING_STATUS) buffer status_block { render_status status; };
layout(std430, set = 0, binding = RTVK_BINDING_BVH_NODES) readonly buffer bvh_node_block {
  bvh_node bvh_nodes[];
};
layout(std430, set = 0, binding = RTVK_BINDING_RAY_COUNT) buffer ray_count_block { uint ray_count[]; };
layout(push_constant) uniform push_block { render_push pc; };

#include "camera.glsl"
#include "random.glsl"
#include "shading.glsl"

void main() {
  // x from the left, y from the top of the image; the dispatch covers one band of rows of the
  // region, for every view.
  if (gl_GlobalInvocationID.x >= pc.region_width || gl_GlobalInvocationID.y >= pc.band_rows) return;
  uint view = gl_GlobalInvocationID.z;
  camera_ubo cam = cams[view];
  uvec2 pixel = uvec2(gl_GlobalInvocationID.x + pc.region_x0, gl_GlobalInvocationID.y + pc.band_y0);

  uint j = cam.image_height - 1u - pixel.y;  // the lesson counts rows from the bottom
  random_stream s = random_stream(pc.seed, pixel.y * cam.image_width + pixel.x, pc.sample_index, 0u);
  precise float x = jitter ? float(pixel.x) + rnd(s, dim_jitter_u) : float(pixel.x);
  precise float y = jitter ? float(j) + rnd(s, dim_jitter_v) : float(j);
  precise float u = pixel_coordinate(x, cam.image_width);
  precise float v = pixel_coordinate(y, cam.image_height);
  precise vec2 lens = any_lens && cam.lens_radius > 0.0
                           ? random_in_unit_disk(rnd(s, dim_lens_a), rnd(s, dim_lens_b))
                           : vec2(0.0);
  uint iterations = 0u;
  uint rays = 0u;
  precise vec3 c = ray_color(get_ray(cam, u, v, lens), s, iterations, rays);
  if (iterations > pc.loop_budget) {
    atomicAdd(status.overrun_pixels, 1u);  // the host fails the render rather than show this
    return;
  }

  // within the view's band
  uint index = (view * pc.band_rows + gl_GlobalInvocationID.y) * pc.region_width + gl_GlobalInvocationID.x;
  if (count_rays) ray_count[index] += rays;
  uint base = 3u * index;
  precise vec3 sum = vec3(rgb[base + 0u], rgb[base + 1u], rgb[base + 2u]) + c;
  rgb[base + 0u] = sum.r;
  rgb[base + 1u] = sum.g;
  rgb[base + 2u] = sum.b;
}
