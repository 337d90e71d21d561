#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "camera.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// The camera's precomputed vectors and lens, rounded to float, and the image size.
camera_ubo to_ubo(const camera& cam);

// The scene's spheres, rounded to float, each with its scene index, in the order `order` gives
// (position -> index into scene::spheres: leaf_layout::spheres, scene order without a BVH).
std::vector<gpu_sphere> to_gpu_spheres(const scene& s, std::span<const std::uint32_t> order);
// Each sphere's velocity (xyz; center1 - center, formed in double), in the same order as
// to_gpu_spheres; empty when no sphere moves.
std::vector<vec4> to_gpu_velocities(const scene& s, std::span<const std::uint32_t> order);
// The scene's quads with their planes (formed in double), rounded to float, each with its scene
// index, in the order `order` gives (position -> index into scene::quads).
std::vector<gpu_quad> to_gpu_quads(const scene& s, std::span<const std::uint32_t> order);
// The scene's triangles, rounded to float, in the order `order` gives (position -> index into
// scene::triangles), and the vertex normals of the smooth ones (three vec4 each, in `normals`).
std::vector<gpu_triangle> to_gpu_triangles(const scene& s, std::span<const std::uint32_t> order,
                                           std::vector<vec4>& normals);
// The scene's materials, in order, rounded to float.
std::vector<gpu_material> to_gpu_materials(const scene& s);

}  // namespace rtvk::gpu
