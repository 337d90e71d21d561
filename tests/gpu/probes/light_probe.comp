#version 450
// Test probe: the third book's densities toward a light and about a normal (pdf.h) on the host's
// lights, points and random numbers, through run_light_probe (light_probe.h), which the tests'
// float compilation runs too.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  light_probe_entry entries[];
};

// pdf.h's table of lights: the probe passes each entry's light by value instead.
const gpu_light lights[1] = gpu_light[1](
    gpu_light(vec3(0.0), 0u, vec3(0.0), 0.0, vec3(0.0), 0.0, vec3(0.0), 0u, vec3(0.0), 0.0, 0.0,
              0u, 0u, 0u));
uint light_count() {
  return 0u;
}

#include "light_probe.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  light_probe_entry e = entries[i];
  run_light_probe(e);
  entries[i] = e;
}
