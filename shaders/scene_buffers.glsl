// The scene's objects and the BVH over them, as gpu_scene (host/gpu/scene/gpu_scene.h) binds
// them: what world.glsl reads. Included by every shader that traces rays through the scene.
#ifndef RTVK_SCENE_BUFFERS_GLSL
#define RTVK_SCENE_BUFFERS_GLSL

layout(std430, set = 0, binding = RTVK_BINDING_SPHERES) readonly buffer sphere_block {
  gpu_sphere spheres[];
};
layout(std430, set = 0, binding = RTVK_BINDING_VELOCITIES) readonly buffer velocity_block {
  vec4 velocities[];
};
layout(std430, set = 0, binding = RTVK_BINDING_QUADS) readonly buffer quad_block {
  gpu_quad quads[];
};
layout(std430, set = 0, binding = RTVK_BINDING_TRIANGLES) readonly buffer triangle_block {
  gpu_triangle triangles[];
};
layout(std430, set = 0, binding = RTVK_BINDING_DISKS) readonly buffer disk_block {
  gpu_disk disks[];
};
layout(std430, set = 0, binding = RTVK_BINDING_NORMALS) readonly buffer normal_block {
  vec4 vertex_normals[];
};
layout(std430, set = 0, binding = RTVK_BINDING_TEXCOORDS) readonly buffer texcoord_block {
  vec2 vertex_uvs[];
};
layout(std430, set = 0, binding = RTVK_BINDING_TANGENTS) readonly buffer tangent_block {
  vec4 vertex_tangents[];
};
layout(std430, set = 0, binding = RTVK_BINDING_INSTANCES) readonly buffer instance_block {
  gpu_instance instances[];
};
layout(std430, set = 0, binding = RTVK_BINDING_BVH_NODES) readonly buffer bvh_node_block {
  bvh_wide_node bvh_nodes[];
};

#include "hit_triangle.h"
// What a triangle hit's shading entry `normals` has beyond normals and uv, set into the record:
// its vertex colors, blended into rec.color, where the third normal's w is their entry (three
// vec4 at 3 * w in vertex_normals; 0 for none); its second texture coordinates, blended into
// rec.uv1, where the second normal's w, read as a uint, has an entry above its bit 0 (three vec2
// at 3 * (w >> 1) in vertex_uvs; 0 for none); its tangents, blended into rec.tangent, where the
// first normal's w has an entry e above its bit 0 (three vec4 at 3 * (e - 1) in
// vertex_tangents; 0 for none).
void record_vertex_extras(uint normals, vec3 weights, precise inout hit_record rec) {
  if (normals == RTVK_FLAT) return;
  uint tangents = uint(vertex_normals[3u * normals].w) >> 1u;
  if (tangents != 0u) {
    uint e = 3u * (tangents - 1u);
    rec.tangent = blend_tangents(vertex_tangents[e], vertex_tangents[e + 1u],
                                 vertex_tangents[e + 2u], weights, rec);
  }
  uint colors = uint(vertex_normals[3u * normals + 2u].w);
  if (colors != 0u)
    rec.color = blend_colors(vertex_normals[3u * colors], vertex_normals[3u * colors + 1u],
                             vertex_normals[3u * colors + 2u], weights);
  uint second = uint(vertex_normals[3u * normals + 1u].w) >> 1u;
  if (second != 0u)
    rec.uv1 = triangle_uv(true, vertex_uvs[3u * second], vertex_uvs[3u * second + 1u],
                          vertex_uvs[3u * second + 2u], weights);
}

#endif
