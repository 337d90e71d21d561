#include "gpu_scene.h"

#include <algorithm>
#include <chrono>

#include <cstring>
#include "bvh.h"
#include "elapsed.h"
#include "packing.h"
#include "wide_bvh.h"

namespace rtvk::gpu {
namespace {

// A buffer cannot be empty: an empty array still takes one element.
template <typename T>
VkDeviceSize bytes_of(const std::vector<T>& v) {
  return std::max<std::size_t>(v.size(), 1) * sizeof(T);
}

std::vector<buffer_spec> with_usage(std::vector<buffer_spec> specs, VkBufferUsageFlags usage) {
  for (buffer_spec& b : specs) b.usage = usage;
  return specs;
}

template <typename T>
void write_array(gpu_buffer& b, const std::vector<T>& v) {
  if (!v.empty()) b.write(v.data(), v.size() * sizeof(T));
}

// Allocation numbers for check_device_fits (the render targets' sets use others).
enum : int { staging_set = 1, array_set };

}  // namespace

gpu_scene::host_arrays gpu_scene::build(const scene& s, bool use_bvh) {
  const auto start = std::chrono::steady_clock::now();
  const bvh tree(use_bvh ? std::span<const sphere>(s.spheres) : std::span<const sphere>(), 0,
                 s.motion);
  const wide_bvh wide(tree);
  const double seconds = seconds_since(start);
  std::vector<bvh_wide_node> nodes(wide.nodes().size());
  static_assert(sizeof(bvh_wide_node) == sizeof(wide_node));
  if (!nodes.empty())
    std::memcpy(nodes.data(), wide.nodes().data(), nodes.size() * sizeof(wide_node));
  return {to_gpu_spheres(s, tree.order()),
          to_gpu_materials(s),
          std::move(nodes),
          to_gpu_velocities(s, tree.order()),
          seconds,
          scene_moves(s)};
}

gpu_scene::gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh)
    : gpu_scene(ctx, build(s, use_bvh)) {}

gpu_scene::gpu_scene(const gpu_context& ctx, const host_arrays& a)
    : sphere_count_(std::uint32_t(a.spheres.size())),
      build_seconds_(a.build_seconds),
      moves_(a.moves),
      specs_{{bytes_of(a.spheres), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.materials), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.nodes), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},
             {bytes_of(a.velocities), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT}},
      staging_(
          host_writes_device_memory(ctx)
              ? std::nullopt
              : std::optional<buffer_set>(std::in_place, ctx, memory_use::staging,
                                          with_usage(specs_, VK_BUFFER_USAGE_TRANSFER_SRC_BIT))),
      arrays_(ctx, staging_ ? memory_use::device_local : memory_use::device_mapped,
              staging_ ? with_usage(specs_, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                                VK_BUFFER_USAGE_TRANSFER_DST_BIT)
                       : specs_) {
  buffer_set& to = staging_ ? *staging_ : arrays_;
  write_array(to[0], a.spheres);
  write_array(to[1], a.materials);
  write_array(to[2], a.nodes);
  write_array(to[3], a.velocities);
}

std::vector<buffer_request> gpu_scene::buffers(const gpu_context& ctx, const host_arrays& a) {
  const VkDeviceSize spheres = bytes_of(a.spheres), materials = bytes_of(a.materials),
                     nodes = bytes_of(a.nodes), velocities = bytes_of(a.velocities);
  using u = memory_use;
  if (host_writes_device_memory(ctx))
    return {{"the sphere array", spheres, true, u::device_mapped, array_set},
            {"the material array", materials, true, u::device_mapped, array_set},
            {"the BVH", nodes, true, u::device_mapped, array_set},
            {"the velocity array", velocities, true, u::device_mapped, array_set}};
  return {{"the spheres' upload copy", spheres, false, u::staging, staging_set},
          {"the sphere array", spheres, true, u::device_local, array_set},
          {"the materials' upload copy", materials, false, u::staging, staging_set},
          {"the material array", materials, true, u::device_local, array_set},
          {"the BVH's upload copy", nodes, false, u::staging, staging_set},
          {"the BVH", nodes, true, u::device_local, array_set},
          {"the velocities' upload copy", velocities, false, u::staging, staging_set},
          {"the velocity array", velocities, true, u::device_local, array_set}};
}

void gpu_scene::record_upload(VkCommandBuffer cb) const {
  if (!staging_) return;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const VkBufferCopy copy{0, 0, specs_[i].size};
    vkCmdCopyBuffer(cb, (*staging_)[i].get(), arrays_[i].get(), 1, &copy);
  }
}

}  // namespace rtvk::gpu
