#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "camera.h"
#include "light_sources.h"
#include "lights_types.h"
#include "scene.h"
#include "scene_tree.h"
#include "shared_types.h"

namespace rtvk::gpu {

// The camera's precomputed vectors and lens, rounded to float, and the image size.
camera_ubo to_ubo(const camera& cam);

// The objects of each kind in the order `slots` gives (scene_tree: position -> the scene's own
// object, or a group's), rounded to float, each with its index in the scan order: the scene
// index for the scene's own, the index in its group's order (spheres, quads, triangles) for a
// group's.
std::vector<gpu_sphere> to_gpu_spheres(const scene& s, std::span<const object_slot> slots);
// Each sphere's velocity (xyz; center1 - center, formed in double), in the same order as
// to_gpu_spheres (a group's spheres stand still); empty when no sphere moves.
std::vector<vec4> to_gpu_velocities(const scene& s, std::span<const object_slot> slots);
// Quads with their planes (formed in double).
std::vector<gpu_quad> to_gpu_quads(const scene& s, std::span<const object_slot> slots);
std::vector<gpu_disk> to_gpu_disks(const scene& s, std::span<const object_slot> slots);
// Triangles, and the shading of those that have some: vertex normals (three vec4 each, in
// `normals`, with gpu_triangle::normals's flags), texture coordinates (three each, in `uvs`) and
// the tangents of those that have some (three each, in `tangents`, in the triangles' order).
std::vector<gpu_triangle> to_gpu_triangles(const scene& s, std::span<const object_slot> slots,
                                           std::vector<vec4>& normals, std::vector<glm::vec2>& uvs,
                                           std::vector<vec4>& tangents);
// The instances, in scene order: the inverse placements and normal matrices rounded to float
// (formed in double), and where their groups are (scene_tree::groups).
std::vector<gpu_instance> to_gpu_instances(const scene& s, std::span<const group_span> groups);
// The scene's materials, in order, rounded to float; a PBR material's gpu_material::pbr is its
// index in to_gpu_pbrs.
std::vector<gpu_material> to_gpu_materials(const scene& s);
// One PBR material's parameters beyond gpu_material's, rounded to float (an infinite
// attenuation_distance is 0).
gpu_pbr to_gpu_pbr(const pbr_material& q);
// The PBR materials' parameters, in the order of the scene's materials of that kind.
std::vector<gpu_pbr> to_gpu_pbrs(const scene& s);
// The scene's textures (pack_textures), rounded to float, and every image's texels in `texels`.
std::vector<gpu_texture> to_gpu_textures(const scene& s, std::vector<std::uint32_t>& texels);
// The noise's tables, the vectors rounded to float.
gpu_perlin to_gpu_perlin(const perlin_tables& p);
// The scene's media (geometry_of), rounded to float.
std::vector<gpu_medium> to_gpu_media(const scene& s);

// One punctual light's kernel record (punctual_record_of, formed in double) rounded to float,
// with the array's light count.
gpu_punctual to_gpu_punctual(const punctual_record& r, std::uint32_t count);
// The scene's punctual lights, in order, each with their count; one unused element (count 0)
// when it has none, so that the shader reads count 0 from a buffer that cannot be empty.
std::vector<gpu_punctual> to_gpu_punctuals(const scene& s);

// The lights sampling aims at (scene_lights), in the shared layout.
std::vector<gpu_light> to_gpu_lights(const std::vector<light_record>& lights);

}  // namespace rtvk::gpu
