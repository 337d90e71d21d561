#include "buffer.h"

#include <cstring>

#include "vk_error.h"

namespace rtvk::gpu {

gpu_buffer::gpu_buffer(const gpu_context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                       memory_use use)
    : ctx_(ctx), device_(ctx.vk()), size_(size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  vk_check(vkCreateBuffer(device_, &info, nullptr, &buffer), "vkCreateBuffer");
  unique_buffer owned(device_, buffer);  // moves into buffer_ once memory_ exists

  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device_, buffer, &req);
  const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
  std::uint32_t type = 0;
  switch (use) {
    case memory_use::device_local:
      type = ctx.memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      break;
    case memory_use::upload:
      type = ctx.memory_type(req.memoryTypeBits, host | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      break;
    case memory_use::readback:
      type = ctx.memory_type(req.memoryTypeBits, host, VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
      break;
  }
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vk_check(vkAllocateMemory(device_, &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = unique_memory(device_, memory);
  buffer_ = std::move(owned);
  vk_check(vkBindBufferMemory(device_, buffer, memory, 0), "vkBindBufferMemory");

  if (use != memory_use::device_local) {
    coherent_ = ctx.memory_type_has(type, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vk_check(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  }
}

gpu_buffer::~gpu_buffer() {
  if (ctx_.lost()) {  // a hung device may still read or write it: leak rather than crash
    buffer_.release();
    memory_.release();
  }
}

void gpu_buffer::write(const void* data, std::size_t bytes) {
  std::memcpy(mapped_, data, bytes);
  if (!coherent_) {
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = memory_.get();
    range.size = VK_WHOLE_SIZE;
    vk_check(vkFlushMappedMemoryRanges(device_, 1, &range), "vkFlushMappedMemoryRanges");
  }
}

const void* gpu_buffer::read() {
  if (!coherent_) {
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = memory_.get();
    range.size = VK_WHOLE_SIZE;
    vk_check(vkInvalidateMappedMemoryRanges(device_, 1, &range), "vkInvalidateMappedMemoryRanges");
  }
  return mapped_;
}

}  // namespace rtvk::gpu
