#include "buffer.h"

#include <algorithm>
#include <cstring>

#include "vk_error.h"

namespace rtvk::gpu {

namespace {

// `families`: the queue families that use it concurrently; empty, one queue's (exclusive). A
// buffer has no layout or compression to lose, so concurrent sharing costs it nothing and spares
// the queues an ownership transfer each way per use.
unique_buffer make_buffer(VkDevice device, VkDeviceSize size, VkBufferUsageFlags usage,
                          const std::vector<std::uint32_t>& families = {}) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (families.size() > 1) {
    info.sharingMode = VK_SHARING_MODE_CONCURRENT;
    info.queueFamilyIndexCount = std::uint32_t(families.size());
    info.pQueueFamilyIndices = families.data();
  }
  VkBuffer buffer = VK_NULL_HANDLE;
  vk_check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
  return unique_buffer(device, buffer);
}

// `addressed`: the memory of a buffer whose device address is taken (acceleration structures and
// their inputs), which must be allocated for it.
unique_memory allocate(VkDevice device, VkDeviceSize size, std::uint32_t type,
                       bool addressed = false) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = size;
  alloc.memoryTypeIndex = type;
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  if (addressed) alloc.pNext = &flags;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vk_check(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
  return unique_memory(device, memory);
}

VkDeviceSize align_up(VkDeviceSize v, VkDeviceSize a) {
  return a > 1 ? (v + a - 1) / a * a : v;
}

}  // namespace

std::uint32_t memory_type_for(const gpu_context& ctx, std::uint32_t type_bits, memory_use use) {
  const VkMemoryPropertyFlags device = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
  const VkMemoryPropertyFlags coherent = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  switch (use) {
    case memory_use::device_local:
      return ctx.memory_type(type_bits, 0, device, host);
    case memory_use::upload:
      return ctx.memory_type(type_bits, host | coherent, device);
    case memory_use::staging:
      return ctx.memory_type(type_bits, host | coherent, 0, device);
    case memory_use::readback:
      return ctx.memory_type(type_bits, host, VK_MEMORY_PROPERTY_HOST_CACHED_BIT, device);
    case memory_use::device_mapped:
      return ctx.memory_type(type_bits, device | host | coherent);
  }
  return ctx.memory_type(type_bits, 0);
}

bool host_writes_device_memory(const gpu_context& ctx) {
  const VkPhysicalDeviceMemoryProperties& m = ctx.memory_properties();
  const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT |
                                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                     VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  VkDeviceSize largest = 0;  // the largest device-local heap
  for (std::uint32_t h = 0; h < m.memoryHeapCount; ++h)
    if (m.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      largest = std::max(largest, m.memoryHeaps[h].size);
  for (std::uint32_t i = 0; i < m.memoryTypeCount; ++i)
    if ((m.memoryTypes[i].propertyFlags & want) == want &&
        m.memoryHeaps[m.memoryTypes[i].heapIndex].size >= largest)
      return true;
  return false;
}

gpu_buffer::gpu_buffer(const gpu_context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                       memory_use use)
    : ctx_(ctx), device_(ctx.vk()), size_(size) {
  unique_buffer owned = make_buffer(device_, size, usage);  // moves into buffer_ after memory_
  VkMemoryRequirements req{};
  vkGetBufferMemoryRequirements(device_, owned.get(), &req);
  const std::uint32_t type = memory_type_for(ctx, req.memoryTypeBits, use);
  memory_ =
      allocate(device_, req.size, type, (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0);
  bound_ = memory_.get();
  buffer_ = std::move(owned);
  vk_check(vkBindBufferMemory(device_, buffer_.get(), bound_, 0), "vkBindBufferMemory");
  if (use != memory_use::device_local) {  // every other use is host-visible
    coherent_ = ctx.memory_type_has(type, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vk_check(vkMapMemory(device_, bound_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
  }
}

gpu_buffer::gpu_buffer(const gpu_context& ctx, unique_buffer buffer, VkDeviceSize size,
                       VkDeviceMemory shared, VkDeviceSize offset, void* mapped, bool coherent)
    : ctx_(ctx),
      device_(ctx.vk()),
      size_(size),
      bound_(shared),
      offset_(offset),
      buffer_(std::move(buffer)),
      mapped_(mapped),
      coherent_(coherent) {}

gpu_buffer::~gpu_buffer() {
  if (ctx_.lost()) {  // a hung device may still read or write it: leak rather than crash
    buffer_.release();
    memory_.release();
  }
}

// From the buffer's offset (aligned to nonCoherentAtomSize by buffer_set) to the end of the
// memory: within the rules for any size.
VkMappedMemoryRange gpu_buffer::range() const {
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
  range.memory = bound_;
  range.offset = offset_;
  range.size = VK_WHOLE_SIZE;
  return range;
}

void gpu_buffer::write(const void* data, std::size_t bytes) {
  std::memcpy(mapped_, data, bytes);
  if (!coherent_) {
    const VkMappedMemoryRange r = range();
    vk_check(vkFlushMappedMemoryRanges(device_, 1, &r), "vkFlushMappedMemoryRanges");
  }
}

const void* gpu_buffer::read() {
  if (!coherent_) {
    const VkMappedMemoryRange r = range();
    vk_check(vkInvalidateMappedMemoryRanges(device_, 1, &r), "vkInvalidateMappedMemoryRanges");
  }
  return mapped_;
}

buffer_set::buffer_set(const gpu_context& ctx, memory_use use, std::span<const buffer_spec> specs)
    : ctx_(ctx) {
  const VkDevice device = ctx.vk();
  std::vector<unique_buffer> made;
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize end = 0;
  std::uint32_t type_bits = ~0u;
  const VkDeviceSize atom =
      use == memory_use::device_local ? 1 : ctx.device().limits.nonCoherentAtomSize;
  for (const buffer_spec& spec : specs) {
    made.push_back(make_buffer(device, spec.size, spec.usage,
                               spec.shared ? ctx.shared_families() : std::vector<std::uint32_t>{}));
    VkMemoryRequirements req{};
    vkGetBufferMemoryRequirements(device, made.back().get(), &req);
    offsets.push_back(align_up(end, std::max(req.alignment, atom)));
    end = offsets.back() + req.size;
    type_bits &= req.memoryTypeBits;
  }
  const std::uint32_t type = memory_type_for(ctx, type_bits, use);
  memory_ = allocate(device, std::max<VkDeviceSize>(end, 1), type);
  char* base = nullptr;
  const bool host_visible = use != memory_use::device_local;
  if (host_visible)
    vk_check(
        vkMapMemory(device, memory_.get(), 0, VK_WHOLE_SIZE, 0, reinterpret_cast<void**>(&base)),
        "vkMapMemory");
  const bool coherent = ctx.memory_type_has(type, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  for (std::size_t i = 0; i < specs.size(); ++i) {
    vk_check(vkBindBufferMemory(device, made[i].get(), memory_.get(), offsets[i]),
             "vkBindBufferMemory");
    buffers_.push_back(std::unique_ptr<gpu_buffer>(
        new gpu_buffer(ctx, std::move(made[i]), specs[i].size, memory_.get(), offsets[i],
                       host_visible ? base + offsets[i] : nullptr, coherent || !host_visible)));
  }
}

buffer_set::~buffer_set() {
  buffers_.clear();                    // the buffers before the memory they are bound to
  if (ctx_.lost()) memory_.release();  // a hung device may still use it
}

}  // namespace rtvk::gpu
