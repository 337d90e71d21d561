#include "gpu_scene.h"

#include <chrono>

#include "bvh.h"
#include "elapsed.h"
#include "packing.h"

namespace rtvk::gpu {
gpu_scene::timed_bvh gpu_scene::build_bvh(const scene& s, bool use_bvh) {
  const auto start = std::chrono::steady_clock::now();
  bvh tree(use_bvh ? std::span<const sphere>(s.spheres) : std::span<const sphere>());
  return {std::move(tree), seconds_since(start)};
}

gpu_scene::gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh)
    : gpu_scene(ctx, s, build_bvh(s, use_bvh)) {}

gpu_scene::gpu_scene(const gpu_context& ctx, const scene& s, const timed_bvh& tree)
    : spheres_(ctx, to_gpu_spheres(s, tree.tree.order())),
      materials_(ctx, to_gpu_materials(s)),
      build_seconds_(tree.seconds),
      nodes_(ctx, tree.tree.nodes()) {}

std::vector<buffer_request> gpu_scene::buffers(const scene& s, bool use_bvh) {
  // The BVH at its largest: N - 1 interior nodes for N >= 2 spheres (one per leaf but one), the
  // root alone for one.
  const VkDeviceSize n = s.spheres.size();
  const VkDeviceSize spheres = std::max<VkDeviceSize>(n, 1) * sizeof(gpu_sphere);
  const VkDeviceSize materials =
      std::max<VkDeviceSize>(s.materials.size(), 1) * sizeof(gpu_material);
  const bool tree = use_bvh && n > 0;
  const VkDeviceSize nodes = (tree ? std::max<VkDeviceSize>(n - 1, 1) : 1) * sizeof(bvh_node);
  using u = memory_use;
  return {{"the spheres' upload copy", spheres, false, u::upload},
          {"the sphere array", spheres, true, u::device_local},
          {"the materials' upload copy", materials, false, u::upload},
          {"the material array", materials, true, u::device_local},
          {"the BVH's upload copy", nodes, false, u::upload},
          {"the BVH", nodes, true, u::device_local}};
}

void gpu_scene::record_upload(VkCommandBuffer cb) const {
  spheres_.record_upload(cb);
  materials_.record_upload(cb);
  nodes_.record_upload(cb);
}

}  // namespace rtvk::gpu
