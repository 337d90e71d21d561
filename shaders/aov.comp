#version 450
// The ground truth beside the image (rtvk render --aov): one invocation per pixel of the window
// follows the ray through the pixel's center (center_ray) to its first hit, as
// host/cpu/render_aov.cpp does on the CPU, and writes what it found (gpu_aov, aov.h).
#extension GL_GOOGLE_include_directive : require
#include "shared_types.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(constant_id = RTVK_SPEC_USE_BVH) const bool use_bvh = true;
layout(constant_id = RTVK_SPEC_TEXTURES) const bool any_textures = false;

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block { camera_ubo cam; };
layout(std430, set = 0, binding = RTVK_BINDING_MATERIALS) readonly buffer material_block {
  gpu_material materials[];
};
layout(std430, set = 0, binding = RTVK_BINDING_AOV) buffer aov_block { gpu_aov aovs[]; };
layout(push_constant) uniform push_block {
  render_push pc;  // the object counts, loop_budget; the window: region_x0, band_y0,
                   // region_width, band_rows
};
#include "scene_buffers.glsl"
#include "appearance_buffers.glsl"

#include "aov.h"
const bool calibrated_cameras = true;  // camera_rays.h: every camera model
#include "camera_rays.h"
#include "texture.h"
#include "world.glsl"

void main() {
  uvec2 at = gl_GlobalInvocationID.xy;
  if (at.x >= pc.region_width || at.y >= pc.band_rows) return;
  uint i = pc.region_x0 + at.x;
  uint j = cam.image_height - 1u - (pc.band_y0 + at.y);  // the lesson counts rows from the bottom
  ray r = center_ray(cam, cam.image_width, cam.image_height, i, j);
  gpu_aov a;
  a.normal = vec3(0.0);
  a.albedo = vec3(0.0);
  a.distance = uintBitsToFloat(0x7f800000u);  // +inf
  a.depth = a.distance;
  a.object = 0u;
  a.instance = 0u;
  a.material = 0u;
  a.hit = 0u;
  hit_record rec;
  uint iterations = 0u;
  bool zero = r.direction == vec3(0.0);  // outside a fisheye's field: nothing seen
  // The first surface that counts (aov_counts), as host/cpu/render_aov.cpp walks to it.
  ray walk = r;
  precise float passed = 0.0;
  bool found = false;
  for (uint k = 0u; k <= max_passes && !zero; ++k) {
    if (!hit_world(walk, 0.001, 3.402823466e+38, rec, iterations)) break;
    gpu_material m = materials[rec.material];
    precise float alpha =
        any_textures ? surface_alpha(m.opacity, m.texture, rec) : m.opacity * rec.color.w;
    found = k == max_passes || aov_counts(m.type, m.flags, rec, alpha, m.alpha_cutoff);
    if (found) break;
    passed += aov_distance(walk, rec);
    walk.origin = scatter_origin(rec, walk.direction);
  }
  if (found) {
    gpu_material m = materials[rec.material];
    precise vec3 color =
        (any_textures ? material_color(m.albedo, m.texture, rec) : m.albedo) * rec.color.xyz;
    a.normal = rec.normal;
    a.albedo = aov_albedo(m.type, color, rec);
    a.distance = passed + aov_distance(walk, rec);
    a.depth = aov_depth(cam.origin, cam.axis_w, rec);
    a.object = hit_object;
    a.instance = hit_instance;
    a.material = rec.material;
    a.hit = 1u;
  }
  aovs[at.y * pc.region_width + at.x] = a;
}
