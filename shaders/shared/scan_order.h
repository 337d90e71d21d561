// The order of the lesson's linear scan, which every search of rtvk reproduces: the scene's own
// objects in scene order, then each instance's in its group's order. An exact tie between two
// hits goes to the later one, so a BVH, the driver's acceleration structure and the scan find
// the same object whatever order they test in. Both backends' searches keep their nearest hit
// with this one rule (host/cpu/bvh_world.cpp, shaders/world.glsl).
#ifndef RTVK_SCAN_ORDER_H
#define RTVK_SCAN_ORDER_H
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

// "No instance": a hit on the scene's own objects is reached through instance 0; instance k of
// the scene's list is k + 1. Both backends count so.
#define RTVK_OWN_OBJECTS 0u

// Whether a hit at the nearest distance so far, on object `index` (its place in its list's scan
// order) reached through `inst`, replaces the nearest hit (`best_index` through `best_inst`;
// best_index -1: none yet): it does when it comes later in the scan.
inline bool later_in_scan(uint inst, int index, uint best_inst, int best_index) {
  return inst > best_inst || (inst == best_inst && index > best_index);
}

RTVK_KERNELS_END

#endif  // RTVK_SCAN_ORDER_H
