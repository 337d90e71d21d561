#version 450
// Test probe: the light tree's draw, point query and trail (light_tree.h) on the host's lamps,
// nodes, points and numbers, through run_light_tree_probe (light_tree_probe.h), which the tests'
// float compilation runs too.
#extension GL_GOOGLE_include_directive : require
#include "probe_types.h"
#include "shared_types.h"

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, set = 0, binding = RTVK_BINDING_PROBE) buffer probe_block {
  light_tree_probe_entry entries[];
};
// pdf.h's table of lights, as gpu_scene binds it.
layout(std430, set = 0, binding = RTVK_BINDING_LIGHTS) readonly buffer light_block {
  gpu_light lights[];
};
uint light_count() {
  return uint(lights.length());
}
#include "light_tree_buffers.glsl"
#include "light_tree_probe.h"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(entries.length())) return;
  light_tree_probe_entry e = entries[i];
  run_light_tree_probe(e);
  entries[i] = e;
}
