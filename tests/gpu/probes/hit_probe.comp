#version 450
// Test probe: hit_sphere of hit_sphere.h for the host's rays, intervals and spheres, so tests can
// feed it what a render rarely meets (degenerate rays) and compare with the C++ compilation of the same function.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block { hit_probe_entry entries[]; };

#include "hit_sphere.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  hit_probe_entry e = entries[i];
  float t;
  entries[i].hit = hit_sphere(e.center, e.radius, ray(e.origin, e.direction, 0.0), e.t_min, e.t_max, t)
                       ? 1u
                       : 0u;
  entries[i].t = t;
}
