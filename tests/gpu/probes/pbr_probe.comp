#version 450
// Test probe: pbr.h's sample, evaluation and density on the host's materials, directions and
// random numbers, through run_pbr_probe (pbr_probe.h), which the tests' float compilation runs
// too.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  pbr_probe_entry entries[];
};

// pbr.h's tables (bsdf_tables.h reads them as bsdf_table[]).
layout(std430, set = 0, binding = RTVK_BINDING_BSDF_TABLES) readonly buffer bsdf_table_block {
  float bsdf_table[];
};

#include "pbr_probe.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  pbr_probe_entry e = entries[i];
  run_pbr_probe(e);
  entries[i] = e;
}
