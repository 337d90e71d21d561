#pragma once
// The scene as the shared header's structs hold it (shaders/shared/shared_types.h): every array the
// GPU's storage buffers get, made on the host. The GPU uploads them (gpu/scene); the CPU's fast
// mode reads them in place (fast/), so both run the same numbers. This header and shared_types.h
// use no kernel type, so that a translation unit compiling the kernels in float can include it.
#include <array>
#include <cstdint>
#include <vector>

#include "lights_types.h"
#include "shared_types.h"

namespace rtvk {
struct scene;
}

namespace rtvk::gpu {

struct scene_arrays {
  std::vector<gpu_sphere> spheres;      // in the BVH's leaf order, or scene order without it
  std::vector<gpu_material> materials;  // in scene order
  std::vector<bvh_wide_node> nodes;     // the four-wide BVH's nodes, depth first (none: empty)
  std::vector<vec4> velocities;         // the spheres', in their order; empty: none moves
  std::vector<gpu_quad> quads;          // in the BVH's leaf order, or scene order without it
  std::vector<gpu_triangle> triangles;  // likewise
  std::vector<gpu_disk> disks;          // likewise
  std::vector<vec4> normals;            // smooth triangles' vertex normals, three each
  double build_seconds = 0;             // building the BVH took
  bool moves = false;                   // some sphere has a velocity
  std::vector<gpu_instance> instances;  // in scene order
  // The scene's own objects of each kind (shape_kind): the first of each array (the groups'
  // follow).
  std::array<std::uint32_t, 4> own{};
  std::vector<glm::vec2> uvs;         // triangles' vertex uv, as `normals`
  std::vector<vec4> tangents;         // vertex tangents of the triangles that have some
  std::vector<gpu_texture> textures;  // by material's texture index
  std::vector<std::uint32_t> texels;  // the images', one after another
  std::vector<gpu_perlin> perlin;     // one: the noise's tables
  std::vector<gpu_medium> media;      // in scene order
  // scene_lights, what lights sampling aims at, then group_lamps (next-event estimation's only)
  std::vector<gpu_light> lights;
  std::uint32_t group_lamps = 0;  // the last entries of `lights` that are group_lamps
  // next-event estimation's light tree over the lamps of `lights` (build_light_tree)
  std::vector<gpu_light_node> light_nodes;
  std::vector<gpu_pbr> pbr;        // the PBR materials' parameters (gpu_material::pbr)
  std::vector<float> bsdf_tables;  // pbr.h's tables (bsdf_tables.h), where `pbr` is not empty
  // The punctual lights (punctual.h), each with their count; one unused element (count 0)
  // when the scene has none.
  std::vector<gpu_punctual> punctual;
  bool with_uv = false;  // some texture reads sphere hits' uv (RTVK_SPEC_UV)
  // The environment map (lights/environment.h): RGBE texels and the sampling table; empty
  // where the scene has none.
  std::vector<std::uint32_t> environment_texels;
  std::vector<float> environment_table;
};

// The scene's arrays, its BVH built (over no objects when !use_bvh).
scene_arrays build_scene_arrays(const scene& s, bool use_bvh);

}  // namespace rtvk::gpu
