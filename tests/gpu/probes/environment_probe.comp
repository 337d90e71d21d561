#version 450
// Test probe: environment.h's lookup, density and sampler on the host's map, directions and
// random numbers, through run_environment_probe (environment_probe.h), which the tests' float
// compilation runs too.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  environment_probe_entry entries[];
};
// The map, as the render binds it (appearance_buffers.glsl).
layout(std430, set = 0, binding = RTVK_BINDING_ENVIRONMENT) readonly buffer environment_block {
  uint environment_texels[];
};
layout(std430, set = 0, binding = RTVK_BINDING_ENVIRONMENT_CDF) readonly buffer environment_cdf_block {
  float environment_table[];
};

#include "environment_probe.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  environment_probe_entry e = entries[i];
  run_environment_probe(e);
  entries[i] = e;
}
