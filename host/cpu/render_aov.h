#pragma once
#include <vector>

#include "camera.h"
#include "render_settings.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk {

// The ground truth of the pixels of `win` (row-major from its top row), as aov.comp finds it on
// the device: the first hit of the ray through each pixel's center (center_ray), its distance,
// z depth, normal, albedo, object and material. `threads`: 0 for all cores.
std::vector<gpu::gpu_aov> render_aov_cpu(const camera& cam, const scene& s,
                                         const render_window& win, int threads = 0);

class bvh_world;
struct scene_shading;
// The same through a world and shading tables already made (cpu_scene keeps them): `shading`
// built without lights (scene_shading(s)).
std::vector<gpu::gpu_aov> render_aov_cpu(const camera& cam, const bvh_world& world,
                                         const scene_shading& shading, const render_window& win,
                                         int threads = 0);

}  // namespace rtvk
