#include "presenter.h"

#include <algorithm>

#include "overlay_push.h"
#include "overlay_shader.h"
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

// The largest band the overlay can take: a whole image's width of text lines is far more than
// it draws (six lines, about 100 characters), so these bound the buffers and the mask's update.
constexpr int max_band_width = 2048, max_band_height = 256;
constexpr VkDeviceSize max_mask_bytes = VkDeviceSize(max_band_width / 32) * max_band_height * 4;
static_assert(max_mask_bytes <= 65536, "the mask goes in one vkCmdUpdateBuffer");

presenter::presenter(gpu::gpu_context& ctx, int width, int height)
    : ctx_(ctx),
      width_(width),
      height_(height),
      overlay_buffers_(
          ctx, gpu::memory_use::device_local,
          std::vector<gpu::buffer_spec>{
              {max_mask_bytes,
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT},
              {VkDeviceSize(max_band_width) * max_band_height * 4,
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT}}) {
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
      gpu::memory_type_for(ctx, req.memoryTypeBits, gpu::memory_use::device_local);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  gpu::vk_check(vkAllocateMemory(ctx.vk(), &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = gpu::unique_memory(ctx.vk(), memory);
  gpu::vk_check(vkBindImageMemory(ctx.vk(), image, memory, 0), "vkBindImageMemory");
}

presenter::~presenter() {
  ctx_.wait_all();
}

void presenter::show_from(VkBuffer bytes) {
  if (compose_ && bytes == bound_bytes_) return;
  const std::vector<gpu::buffer_binding> bindings{
      {RTVK_OVERLAY_BYTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, bytes},
      {RTVK_OVERLAY_MASK, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, overlay_buffers_[0].get()},
      {RTVK_OVERLAY_BAND, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, overlay_buffers_[1].get()}};
  if (!compose_) {
    compose_ = std::make_unique<gpu::compute_pipeline>(ctx_, overlay_shader(), bindings,
                                                       sizeof(gpu::overlay_push));
  } else {
    ctx_.wait_all();  // the set may not change under a frame in flight
    compose_->rebind(bindings);
  }
  bound_bytes_ = bytes;
}

// overlay.comp over the band: the mask in, the composed band out, ready to copy.
void presenter::record_overlay(VkCommandBuffer cb, const overlay_mask& overlay) const {
  // The last frame's reads of the mask and writes of the band come first.
  VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  before.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
  vkCmdUpdateBuffer(cb, overlay_buffers_[0].get(), 0, overlay.bits.size() * 4, overlay.bits.data());
  VkMemoryBarrier ready{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  ready.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  ready.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &ready, 0, nullptr, 0, nullptr);
  compose_->bind(cb);
  const gpu::overlay_push push{std::uint32_t(overlay.width), std::uint32_t(overlay.height),
                               std::uint32_t(width_), std::uint32_t(overlay.words_per_row)};
  compose_->push(cb, &push, sizeof push);
  compose_->dispatch(cb, {(push.width + 63) / 64, push.height, 1});
  VkMemoryBarrier done{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  done.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  done.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                       1, &done, 0, nullptr, 0, nullptr);
}

void presenter::record(VkCommandBuffer cb, const overlay_mask& overlay, const swapchain& chain,
                       std::uint32_t target) const {
  const VkBuffer bytes = bound_bytes_;
  // The bytes were written by the compute queue's last batch, which the host waited for: on
  // another family's queue (gpu_context::split_queues) that wait orders them and this barrier
  // makes them visible; on one queue the engine's own barrier already did.
  VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  written.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                       &written, 0, nullptr, 0, nullptr);
  const bool band = overlay.width > 0 && overlay.height > 0 && overlay.width <= max_band_width &&
                    overlay.height <= max_band_height;
  if (band) record_overlay(cb, overlay);
  const VkImage src = image_.get(), dst = chain.image(target);
  barrier(cb, src, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {std::uint32_t(width_), std::uint32_t(height_), 1};
  vkCmdCopyBufferToImage(cb, bytes, src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
  if (band) {  // over the same pixels: the copies are ordered
    barrier(cb, src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy over{};
    over.bufferRowLength = std::uint32_t(overlay.width);
    over.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    over.imageExtent = {std::uint32_t(overlay.width), std::uint32_t(overlay.height), 1};
    vkCmdCopyBufferToImage(cb, overlay_buffers_[1].get(), src, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &over);
  }
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
