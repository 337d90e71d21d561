#pragma once
#include <cstddef>

#include "context.h"
#include "vk_handle.h"

namespace rtvk::gpu {

enum class memory_use {
  device_local,  // read and written by shaders; filled and read back by copies
  upload,        // written by the host, read by the device (host-visible, coherent)
  readback,      // written by the device, read by the host (host-visible, cached if possible)
};

// A buffer with its own memory allocation, persistently mapped unless device-local.
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
  // Destroyed in reverse order: the buffer, then its memory (which unmaps it).
  const gpu_context& ctx_;  // tells whether the device may still be using the buffer
  VkDevice device_;         // owner of both handles
  VkDeviceSize size_;       // bytes
  unique_memory memory_;    // the allocation
  unique_buffer buffer_;    // bound to memory_ at offset 0
  void* mapped_ = nullptr;  // host address of memory_, when host-visible
  bool coherent_ = true;    // false: flush and invalidate by hand
};

}  // namespace rtvk::gpu
