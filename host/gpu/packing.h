#pragma once
#include <vector>

#include "camera.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// The camera's four precomputed vectors, rounded to float, and the image size.
camera_ubo to_ubo(const camera& cam);

// The scene's spheres, in order, rounded to float.
std::vector<gpu_sphere> to_gpu_spheres(const scene& s);

}  // namespace rtvk::gpu
