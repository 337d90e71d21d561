#pragma once
#include <vector>

#include "camera.h"
#include "context.h"
#include "render_settings.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// Runs aov.comp: the first hit of the ray through each pixel center of `win` (row-major from its
// top row), on the device, through the scene's BVH (or every object in turn). The scene is put
// on the device for the pass alone: the AOVs are drawn once per image, beside the render.
std::vector<gpu_aov> run_aov_pass(gpu_context& ctx, const scene& s, bool use_bvh, const camera& cam,
                                  const render_window& win);

}  // namespace rtvk::gpu
