#pragma once
#include <string>
#include <vector>

#include "buffer.h"
#include "context.h"

namespace rtvk::gpu {

// A buffer a render is about to allocate, described so it can be checked before any is.
struct buffer_request {
  std::string what;     // for messages: "the BVH nodes", "the spheres"
  VkDeviceSize bytes;   // its size
  bool storage;         // bound whole as one storage buffer (maxStorageBufferRange applies)
  memory_use use;       // which memory it lives in
  int allocation = -1;  // requests with the same number share one memory allocation (a
                        // buffer_set); -1: one of its own
};

// Checks every buffer against the device before anything is allocated: each storage buffer
// within maxStorageBufferRange, each allocation (a buffer of its own, or a buffer_set's) within
// maxMemoryAllocationSize,
// their number within maxMemoryAllocationCount, and the sum in each memory heap within the heap.
// A shader reading past a buffer bound too large gives a wrong image or a device fault on a
// device without robust buffer access, so this refuses instead: usage_error beginning with
// `subject` (e.g. "--scene spheres:4000000"), naming the buffer, its size, the device and its
// limit.
void check_device_fits(const gpu_context& ctx, const std::vector<buffer_request>& buffers,
                       const std::string& subject);

}  // namespace rtvk::gpu
