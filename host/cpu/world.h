#pragma once
#include <memory>

#include "hittable_list.h"
#include "scene.h"

namespace rtvk {

// The lesson's world: every object of the scene in a hittable_list, tested in order (spheres,
// quads, triangles).
hittable_list make_world(const scene& s);

// The world the rays are traced against: the lesson's hittable_list, or the BVH over the same
// objects in the same order (identical hits, faster).
std::unique_ptr<hittable> make_accelerated_world(const scene& s, bool use_bvh, int threads = 0);

}  // namespace rtvk
