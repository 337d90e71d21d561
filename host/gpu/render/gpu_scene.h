#pragma once
#include <cstdint>
#include <vector>

#include "buffer.h"
#include "bvh.h"
#include "context.h"
#include "device_fit.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// A storage buffer filled from host data through a staging copy recorded into a command buffer.
template <typename T>
struct device_array {
  device_array(const gpu_context& ctx, std::vector<T> data)
      : count(data.size()),
        bytes((data.empty() ? 1 : data.size()) * sizeof(T)),
        staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, memory_use::upload),
        buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               memory_use::device_local) {
    if (data.empty()) data.resize(1);  // a buffer cannot be empty; `count` says 0
    staging.write(data.data(), bytes);
  }
  void record_upload(VkCommandBuffer cb) const {
    const VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cb, staging.get(), buffer.get(), 1, &copy);
  }
  std::size_t count;   // elements the scene has
  VkDeviceSize bytes;  // buffer size
  gpu_buffer staging;  // host copy
  gpu_buffer buffer;   // what the shader reads
};

// The scene on the device: its spheres and materials in the shared header's layout, and the BVH
// over the spheres (an empty one when the render tests every sphere). With the BVH the spheres
// are stored in its leaf order, each with its scene index; without it, in scene order. Filled on
// the host when made; the copies to the device are recorded into the first submission.
class gpu_scene {
 public:
  gpu_scene(const gpu_context& ctx, const scene& s, bool use_bvh);

  // The buffers a gpu_scene of `s` allocates, at their largest, for check_device_fits.
  static std::vector<buffer_request> buffers(const scene& s, bool use_bvh);

  void record_upload(VkCommandBuffer cb) const;

  std::uint32_t sphere_count() const { return std::uint32_t(spheres_.count); }
  double build_seconds() const { return build_seconds_; }
  VkBuffer spheres() const { return spheres_.buffer.get(); }
  VkBuffer materials() const { return materials_.buffer.get(); }
  VkBuffer nodes() const { return nodes_.buffer.get(); }

 private:
  struct timed_bvh {
    bvh tree;        // over the scene's spheres, or empty
    double seconds;  // its build took
  };
  static timed_bvh build_bvh(const scene& s, bool use_bvh);
  gpu_scene(const gpu_context& ctx, const scene& s, const timed_bvh& tree);

  device_array<gpu_sphere> spheres_;      // in the BVH's leaf order, or scene order without it
  device_array<gpu_material> materials_;  // in scene order
  double build_seconds_;                  // building the BVH took
  device_array<bvh_node> nodes_;          // the BVH's interior nodes, depth first
};

}  // namespace rtvk::gpu
