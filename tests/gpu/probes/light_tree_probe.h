// The body of the light tree's probe, in the kernels' language: light_tree_probe.comp and the
// tests' float compilation (tests/gpu/kernels_f32.cpp) run it on the same entries, lamps and
// nodes, so whatever they disagree on is the device's arithmetic.
#ifndef RTVK_LIGHT_TREE_PROBE_H
#define RTVK_LIGHT_TREE_PROBE_H
#include "kernel_lang.h"
#include "light_tree.h"
#include "probe_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::light_tree_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

inline void run_light_tree_probe(LIGHTS_PARAM INOUT(light_tree_probe_entry) e) {
  precise real pmf;
  e.lamp = light_tree_draw(LIGHTS e.p, e.n, e.u, pmf);
  e.pmf = float(pmf);
  uint leaf;
  bool found = light_tree_find(LIGHTS e.p, e.d, real(0.0), e.t_hit, leaf);
  e.found = found ? 1u : 0u;
  e.leaf = leaf;
  e.leaf_pmf = found ? float(light_tree_trail_pmf(LIGHTS e.p, e.n, LIGHT_NODE(leaf).second)) : 0.0f;
}

RTVK_KERNELS_END

#endif  // RTVK_LIGHT_TREE_PROBE_H
