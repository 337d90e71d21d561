#pragma once
#include <cstdint>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// Device time of one submission at a time, from two timestamp queries: one written before the
// submission's first command, one after its last. Where the queue has no timestamps it records
// nothing and reads 0.
class device_timer {
 public:
  explicit device_timer(const gpu_context& ctx);
  ~device_timer();
  device_timer(const device_timer&) = delete;
  device_timer& operator=(const device_timer&) = delete;

  bool available() const { return pool_.get() != VK_NULL_HANDLE; }
  void record_begin(VkCommandBuffer cb) const;  // first in the command buffer
  void record_end(VkCommandBuffer cb) const;    // last in the command buffer
  // Seconds between the two, once the submission has completed; 0 when not available.
  double seconds() const;

 private:
  const gpu_context& ctx_;  // tells whether the device may still be using the pool
  double period_ns_;        // nanoseconds per timestamp tick
  std::uint64_t mask_;      // the bits a timestamp holds
  unique_query_pool pool_;  // two queries; empty when the queue has no timestamps
};

}  // namespace rtvk::gpu
