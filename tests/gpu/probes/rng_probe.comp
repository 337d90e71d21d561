#version 450
// Test probe: the random numbers for the host's counters, to compare bit for bit with the C++.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block { rng_probe_entry entries[]; };

#include "random.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  rng_probe_entry e = entries[i];
  entries[i].bits = random_bits(0x5eedu, e.pixel, e.sample_index, e.bounce, e.dim);
  entries[i].value = random_float(0x5eedu, e.pixel, e.sample_index, e.bounce, e.dim);
  vec2 turn = turn_cos_sin(entries[i].value);
  entries[i].turn_cos = turn.x;
  entries[i].turn_sin = turn.y;
}
