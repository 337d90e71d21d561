#include "device_fit.h"

#include <map>

#include "errors.h"
#include "format.h"

namespace rtvk::gpu {
namespace {

// The heap gpu_buffer's memory for `use` comes from (the memory type it would pick for a buffer
// that any type can hold).
std::uint32_t heap_for(const gpu_context& ctx, memory_use use) {
  return ctx.memory_properties().memoryTypes[memory_type_for(ctx, ~0u, use)].heapIndex;
}

}  // namespace

void check_device_fits(const gpu_context& ctx, const std::vector<buffer_request>& buffers,
                       const std::string& subject) {
  const device_info& dev = ctx.device();
  const std::string device = "device '" + dev.name + "'";
  std::map<std::uint32_t, VkDeviceSize> per_heap;
  // Each allocation: its size and what it holds, for messages.
  struct allocation {
    VkDeviceSize bytes = 0;
    std::string what;
  };
  std::vector<allocation> allocations;
  std::map<int, std::size_t> shared;  // allocation number -> index into allocations
  for (const buffer_request& b : buffers) {
    if (b.storage && b.bytes > dev.limits.maxStorageBufferRange)
      throw usage_error(subject + ": " + b.what + " needs " + format_bytes(b.bytes) +
                        " in one storage buffer; " + device + " allows " +
                        format_bytes(dev.limits.maxStorageBufferRange));
    per_heap[heap_for(ctx, b.use)] += b.bytes;
    if (b.allocation < 0 || !shared.count(b.allocation)) {
      if (b.allocation >= 0) shared[b.allocation] = allocations.size();
      allocations.push_back({0, b.what});
    } else {
      allocations[shared[b.allocation]].what += " and " + b.what;
    }
    allocations[b.allocation < 0 ? allocations.size() - 1 : shared[b.allocation]].bytes += b.bytes;
  }
  for (const allocation& a : allocations)
    if (dev.max_allocation_size != 0 && a.bytes > dev.max_allocation_size)
      throw usage_error(subject + ": " + a.what + " need" +
                        (a.what.find(" and ") != std::string::npos ? "" : "s") + " " +
                        format_bytes(a.bytes) + " in one memory allocation; " + device +
                        " allows " + format_bytes(dev.max_allocation_size));
  if (allocations.size() > dev.limits.maxMemoryAllocationCount)
    throw usage_error(subject + ": the render needs " + std::to_string(allocations.size()) +
                      " memory allocations; " + device + " allows " +
                      std::to_string(dev.limits.maxMemoryAllocationCount));
  const std::vector<gpu_context::heap_room> rooms = ctx.heap_rooms();
  for (const auto& [heap, bytes] : per_heap) {
    const gpu_context::heap_room room = rooms[heap];
    if (bytes > room.bytes)
      throw usage_error(subject + ": the render needs " + format_bytes(bytes) + " of memory heap " +
                        std::to_string(heap) + "; " + device + " has " + format_bytes(room.bytes) +
                        (room.from_budget ? " of it to spare (VK_EXT_memory_budget)" : " there"));
  }
}

}  // namespace rtvk::gpu
