#include "presenter.h"

#include <algorithm>

#include "vk_error.h"

namespace rtvk::view {
namespace {

void barrier(VkCommandBuffer cb, VkImage image, VkImageLayout from, VkImageLayout to,
             VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
             VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.srcAccessMask = src_access;
  b.dstAccessMask = dst_access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

// The largest rectangle of the source's aspect inside the target, centred.
void fit(int src_w, int src_h, VkExtent2D target, VkOffset3D& lo, VkOffset3D& hi) {
  const double scale = std::min(double(target.width) / src_w, double(target.height) / src_h);
  const int w = std::max(1, int(src_w * scale)), h = std::max(1, int(src_h * scale));
  lo = {int(target.width - w) / 2, int(target.height - h) / 2, 0};
  hi = {lo.x + w, lo.y + h, 1};
}

}  // namespace

presenter::presenter(gpu::gpu_context& ctx, int width, int height)
    : ctx_(ctx), width_(width), height_(height) {
  const VkDeviceSize bytes = VkDeviceSize(width) * VkDeviceSize(height) * 4;
  staging_ = std::make_unique<gpu::gpu_buffer>(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                               gpu::memory_use::upload);
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = VK_FORMAT_R8G8B8A8_UNORM;
  info.extent = {std::uint32_t(width), std::uint32_t(height), 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  gpu::vk_check(vkCreateImage(ctx.vk(), &info, nullptr, &image), "vkCreateImage");
  image_ = gpu::unique_image(ctx.vk(), image);
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(ctx.vk(), image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      ctx.memory_type(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  gpu::vk_check(vkAllocateMemory(ctx.vk(), &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = gpu::unique_memory(ctx.vk(), memory);
  gpu::vk_check(vkBindImageMemory(ctx.vk(), image, memory, 0), "vkBindImageMemory");
}

presenter::~presenter() {
  ctx_.wait_all();
}

void presenter::write(const std::uint32_t* rgba) {
  staging_->write(rgba, std::size_t(width_) * std::size_t(height_) * 4);
}

void presenter::record(VkCommandBuffer cb, const swapchain& chain, std::uint32_t target) const {
  const VkImage src = image_.get(), dst = chain.image(target);
  barrier(cb, src, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {std::uint32_t(width_), std::uint32_t(height_), 1};
  vkCmdCopyBufferToImage(cb, staging_->get(), src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  barrier(cb, src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT);
  // The swapchain image: its old contents are not needed.
  barrier(cb, dst, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkClearColorValue black{{0, 0, 0, 1}};
  const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cb, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &all);
  barrier(cb, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {width_, height_, 1};
  blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  fit(width_, height_, chain.extent(), blit.dstOffsets[0], blit.dstOffsets[1]);
  vkCmdBlitImage(cb, src, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_NEAREST);
  barrier(cb, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
          VK_ACCESS_TRANSFER_WRITE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
}

}  // namespace rtvk::view
