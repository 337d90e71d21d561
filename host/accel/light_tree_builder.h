#pragma once
#include <vector>

#include "lights_types.h"
#include "pdf.h"
#include "sphere.h"

namespace rtvk {

// Next-event estimation's light tree (shaders/shared/lights/light_tree.h reads it) over the
// drawable lamps of `lights` (RTVK_LIGHT_EMITS and lamp_power > 0; the others are skipped, their
// light found by the paths that hit them): each leaf one lamp, its `lamp` the index in `lights`.
// Split by pbrt-v4's surface area orientation heuristic over 12 buckets an axis, at the centroids'
// median along their widest axis where that finds no split or the tree would grow deeper than
// light_tree_depth. One unused node (power 0) where nothing can be drawn.
// A moving sphere is bounded over `motion` (the instants rays sample).
std::vector<gpu::gpu_light_node> build_light_tree(const std::vector<light_record>& lights,
                                                  time_span motion = {});

}  // namespace rtvk
