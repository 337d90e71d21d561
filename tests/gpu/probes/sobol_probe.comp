#version 450
// Test probe: sobol.h's low-discrepancy numbers for the host's counters, to compare bit for bit
// with the C++.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  sobol_probe_entry entries[];
};

#include "random.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  sobol_probe_entry e = entries[i];
  random_stream s = at_bounce(pixel_sample_stream(0x5eedu, e.pixel, e.sample_index), e.bounce);
  entries[i].bits = sobol_bits(s, e.dim);
  uvec2 b = sobol_bits2(s, e.dim);
  entries[i].bits_x = b.x;
  entries[i].bits_y = b.y;
  entries[i].value = sobol_rnd(s, e.dim);
  vec2 v = sobol_rnd2(s, e.dim);
  entries[i].value_x = v.x;
  entries[i].value_y = v.y;
}
