#include "scene_arrays.h"

#include <chrono>
#include <cstring>

#include "bsdf_tables.h"
#include "elapsed.h"
#include "light_tree_builder.h"
#include "packing.h"
#include "scene.h"
#include "scene_tree.h"
#include "wide_bvh.h"

namespace rtvk::gpu {

static_assert(std::tuple_size_v<kind_counts> == std::tuple_size_v<decltype(scene_arrays::own)>);

scene_arrays build_scene_arrays(const scene& s, bool use_bvh) {
  const auto start = std::chrono::steady_clock::now();
  const scene_tree tree =
      build_scene_tree(spans_of(s), s.groups, s.instances, use_bvh, 0, s.motion);
  const double seconds = seconds_since(start);
  std::vector<bvh_wide_node> nodes(tree.nodes.size());
  static_assert(sizeof(bvh_wide_node) == sizeof(wide_node));
  if (!nodes.empty())
    std::memcpy(nodes.data(), tree.nodes.data(), nodes.size() * sizeof(wide_node));
  scene_arrays a;
  a.spheres = to_gpu_spheres(s, tree.slots[shape_sphere]);
  a.materials = to_gpu_materials(s);
  a.nodes = std::move(nodes);
  a.velocities = to_gpu_velocities(s, tree.slots[shape_sphere]);
  a.quads = to_gpu_quads(s, tree.slots[shape_quad]);
  a.triangles = to_gpu_triangles(s, tree.slots[shape_triangle], a.normals, a.uvs, a.tangents);
  a.disks = to_gpu_disks(s, tree.slots[shape_disk]);
  a.build_seconds = seconds;
  a.moves = scene_moves(s);
  a.instances = to_gpu_instances(s, tree.groups);
  a.own = {std::uint32_t(s.spheres.size()), std::uint32_t(s.quads.size()),
           std::uint32_t(s.triangles.size()), std::uint32_t(s.disks.size())};
  a.textures = to_gpu_textures(s, a.texels);
  a.perlin = {to_gpu_perlin(make_perlin(s.noise_seed))};
  a.media = to_gpu_media(s);
  // Lights sampling aims at scene_lights; next-event estimation draws their lamps and those
  // inside groups, appended (the books' scenes have none: their array is what it was).
  std::vector<light_record> lights = scene_lights(s);
  const std::vector<light_record> placed_lamps = group_lamps(s);
  lights.insert(lights.end(), placed_lamps.begin(), placed_lamps.end());
  a.lights = to_gpu_lights(lights);
  a.group_lamps = std::uint32_t(placed_lamps.size());
  a.light_nodes = build_light_tree(lights, s.motion);
  a.pbr = to_gpu_pbrs(s);
  if (!a.pbr.empty()) a.bsdf_tables.assign(std::begin(bsdf_table_data), std::end(bsdf_table_data));
  a.punctual = to_gpu_punctuals(s);
  a.with_uv = scene_reads_uv(s);
  if (s.environment) {
    a.environment_texels = s.environment->image->texels;
    a.environment_table = environment_table_of(*s.environment);
  }
  return a;
}

}  // namespace rtvk::gpu
