#pragma once
#include <vector>

#include "camera.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// The camera's precomputed vectors and lens, rounded to float, and the image size.
camera_ubo to_ubo(const camera& cam);

// The scene's spheres and materials, in order, rounded to float.
std::vector<gpu_sphere> to_gpu_spheres(const scene& s);
std::vector<gpu_material> to_gpu_materials(const scene& s);

}  // namespace rtvk::gpu
