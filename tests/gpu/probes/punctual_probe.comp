#version 450
// Test probe: punctual.h's sample, count, sun radiance and sun density on the host's lights,
// points and random numbers, through run_punctual_probe (punctual_probe.h), which the tests' float
// compilation runs too.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "lights_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  punctual_probe_entry entries[];
};

#include "punctual_buffers.glsl"
#include "punctual_probe.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  punctual_probe_entry e = entries[i];
  run_punctual_probe(e);
  entries[i] = e;
}
