#version 450
// Test probe: hit_world (world.glsl, the GPU's own traversal) along the host's rays, so tests can
// hold its closest hits against the CPU's four-wide traversal on the same rays.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;
layout(constant_id = RTVK_SPEC_USE_BVH) const bool use_bvh = true;

#include "scene_buffers.glsl"
layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  world_probe_entry entries[];
};
layout(push_constant) uniform push_block {
  render_push pc;  // the object counts and loop_budget
};

#include "world.glsl"
#include "normal_map.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  ray r = ray(entries[i].origin, entries[i].direction, 0.0);
  hit_record rec;
  uint iterations = 0u;
  bool hit = hit_world(r, 0.001, 3.402823466e+38, rec, iterations);
  entries[i].hit = hit ? 1u : 0u;
  entries[i].t = hit ? rec.t : 0.0;
  entries[i].normal = hit ? rec.normal : vec3(0.0);
  entries[i].material = hit ? rec.material : 0u;
  entries[i].iterations = iterations;
  entries[i].tangent = hit ? rec.tangent : vec4(0.0);
  entries[i].mapped = hit ? normal_mapped(rec, entries[i].texel, entries[i].scale,
                                          -normalize(entries[i].direction))
                          : vec3(0.0);
}
