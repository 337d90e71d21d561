#pragma once
#include <cstdint>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// Device time of submissions, from two timestamp queries each: one written before the
// submission's first command, one after its last. One pair per submission slot of the context
// (gpu_context::submission_slots), so submissions in flight together each keep their own. Where
// the queue has no timestamps it records nothing and reads 0.
class device_timer {
 public:
  explicit device_timer(const gpu_context& ctx);
  ~device_timer();
  device_timer(const device_timer&) = delete;
  device_timer& operator=(const device_timer&) = delete;

  bool available() const { return pool_.get() != VK_NULL_HANDLE; }
  // For submission `ticket` (gpu_context::next_ticket while recording it).
  void record_begin(VkCommandBuffer cb, std::uint64_t ticket) const;  // first in the buffer
  void record_end(VkCommandBuffer cb, std::uint64_t ticket) const;    // last in the buffer
  // Seconds between the two -- or from the end of the submission read before, where the two
  // overlapped -- once submission `ticket` has completed and before its slot is reused; read in
  // ticket order. 0 when not available.
  double seconds(std::uint64_t ticket) const;

 private:
  const gpu_context& ctx_;              // tells whether the device may still be using the pool
  double period_ns_;                    // nanoseconds per timestamp tick
  std::uint64_t mask_;                  // the bits a timestamp holds
  mutable std::uint64_t last_end_ = 0;  // the last timestamp read, ticks
  unique_query_pool pool_;  // two queries per slot; empty when the queue has no timestamps
};

}  // namespace rtvk::gpu
