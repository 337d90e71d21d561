#pragma once
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

// What a buffer is for, which decides the memory type it lives in (memory_type_for): by
// property preference, among the types its buffers allow, never a protected, lazily allocated
// or AMD device-coherent one where another fits.
enum class memory_use {
  device_local,   // read and written by shaders, filled and read back by copies: device-local,
                  // not host-visible where there is a choice (the host-visible window is scarce)
  upload,         // written by the host, read by shaders every dispatch (the camera block, the
                  // byte thresholds): host-visible and coherent, device-local where it can be
                  // (ReBAR, unified memory, the 256 MiB BAR window)
  staging,        // written by the host once and copied: host-visible and coherent, not device-
                  // local where there is a choice
  readback,       // written by copies, read by the host: host-visible, host-cached if possible,
                  // not device-local where there is a choice (reading VRAM over PCIe is slow)
  device_mapped,  // read by shaders, written once by the host in place: device-local, host-
                  // visible and coherent (ReBAR, unified memory; see host_writes_device_memory)
};

// The memory type a buffer of `use` lives in, among those `type_bits` allows.
std::uint32_t memory_type_for(const gpu_context& ctx, std::uint32_t type_bits, memory_use use);

// Whether the host can write the device's main memory directly: a device-local, host-visible,
// coherent type in the largest device-local heap (unified memory, or a discrete GPU with
// resizable BAR), so uploads need no second copy. The 256 MiB BAR window of other discrete GPUs
// is a heap of its own and does not count.
bool host_writes_device_memory(const gpu_context& ctx);

// A buffer, persistently mapped unless it is a device_local one: with its own memory allocation, or
// placed in a buffer_set's.
class gpu_buffer {
 public:
  gpu_buffer(const gpu_context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, memory_use use);
  ~gpu_buffer();
  gpu_buffer(const gpu_buffer&) = delete;
  gpu_buffer& operator=(const gpu_buffer&) = delete;

  VkBuffer get() const { return buffer_.get(); }
  VkDeviceSize size() const { return size_; }

  // Copies host data in (upload buffers).
  void write(const void* data, std::size_t bytes);
  // Makes device writes visible to the host and returns the mapped bytes (readback buffers).
  const void* read();

 private:
  friend class buffer_set;
  // A buffer bound into memory `shared` (owned by a buffer_set) at `offset`; `mapped` is the
  // host address of that offset, or null.
  gpu_buffer(const gpu_context& ctx, unique_buffer buffer, VkDeviceSize size, VkDeviceMemory shared,
             VkDeviceSize offset, void* mapped, bool coherent);
  VkMappedMemoryRange range() const;

  // Destroyed in reverse order: the buffer, then its memory (which unmaps it).
  const gpu_context& ctx_;  // tells whether the device may still be using the buffer
  VkDevice device_;         // owner of both handles
  VkDeviceSize size_;       // bytes
  unique_memory memory_;    // its own allocation; empty when placed in a buffer_set's
  VkDeviceMemory bound_ = VK_NULL_HANDLE;  // the memory it is bound to (memory_'s or a set's)
  VkDeviceSize offset_ = 0;                // where in bound_
  unique_buffer buffer_;                   // bound to bound_ at offset_
  void* mapped_ = nullptr;  // host address of the buffer's first byte, when host-visible
  bool coherent_ = true;    // false: flush and invalidate by hand
};

// What a buffer_set holds: one buffer's size and usage.
struct buffer_spec {
  VkDeviceSize size;         // bytes
  VkBufferUsageFlags usage;  // what it is bound and copied as
  bool shared = false;       // used by the presenting queue too: concurrent between the families
                             // when they differ (gpu_context::split_queues)
};

// Several buffers of one memory use in one memory allocation, each at an offset its alignment
// (and, for host-visible memory, the device's flush granularity) allows: a render's dozen buffers
// cost a handful of allocations, not one each. The buffers go before the memory.
class buffer_set {
 public:
  buffer_set(const gpu_context& ctx, memory_use use, std::span<const buffer_spec> specs);
  ~buffer_set();
  buffer_set(const buffer_set&) = delete;
  buffer_set& operator=(const buffer_set&) = delete;

  gpu_buffer& operator[](std::size_t i) { return *buffers_[i]; }
  const gpu_buffer& operator[](std::size_t i) const { return *buffers_[i]; }

 private:
  const gpu_context& ctx_;                            // tells whether the device may use it
  unique_memory memory_;                              // the one allocation
  std::vector<std::unique_ptr<gpu_buffer>> buffers_;  // in spec order
};

}  // namespace rtvk::gpu
