// Which hits on a surface count: glTF's alpha modes and back-face culling, decided alike by the
// renderers (ray_color.h's path_passes, a ray let through going on beyond the surface) and by
// the AOVs (aov.h).
#ifndef RTVK_SURFACE_H
#define RTVK_SURFACE_H
#include "appearance_types.h"
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

// Surfaces one path may pass through (alpha, cull_back) before the next one counts whatever its
// alpha: no path loops forever, and each pass is a step of the GPU's loop budget.
const uint max_passes = 16u;

// Whether a hit on a surface with these material flags (RTVK_MATERIAL_*) counts: false where a
// back face is culled (never a dielectric's: a ray inside glass leaves through its back), where
// a mask's alpha is below the cutoff, and, for a blend, with probability 1 - alpha (u uniform in
// [0, 1); the AOVs pass 1/2, so a blend counts for them where alpha > 1/2).
inline bool surface_counts(uint type, uint flags, bool front_face, real alpha, real cutoff,
                           real u) {
  if ((flags & RTVK_MATERIAL_CULL_BACK) != 0u && !front_face && type != RTVK_MATERIAL_DIELECTRIC)
    return false;
  if ((flags & RTVK_MATERIAL_ALPHA_MASK) != 0u) return alpha >= cutoff;
  if ((flags & RTVK_MATERIAL_ALPHA_BLEND) != 0u) return u < alpha;
  return true;
}

RTVK_KERNELS_END

#endif  // RTVK_SURFACE_H
