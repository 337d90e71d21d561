#include "device_timer.h"

#include <algorithm>

#include "vk_error.h"

namespace rtvk::gpu {
namespace {

unique_query_pool make_pool(const gpu_context& ctx) {
  if (ctx.device().timestamp_valid_bits == 0) return {};
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = 2 * gpu_context::submission_slots;
  VkQueryPool pool = VK_NULL_HANDLE;
  vk_check(vkCreateQueryPool(ctx.vk(), &info, nullptr, &pool), "vkCreateQueryPool");
  return unique_query_pool(ctx.vk(), pool);
}

}  // namespace

device_timer::device_timer(const gpu_context& ctx)
    : ctx_(ctx),
      period_ns_(ctx.device().limits.timestampPeriod),
      mask_(ctx.device().timestamp_valid_bits >= 64
                ? ~std::uint64_t(0)
                : (std::uint64_t(1) << ctx.device().timestamp_valid_bits) - 1),
      pool_(make_pool(ctx)) {}

device_timer::~device_timer() {
  if (ctx_.lost()) pool_.release();  // a hung device may still write to it
}

namespace {
std::uint32_t first_query(std::uint64_t ticket) {
  return std::uint32_t(2 * (ticket % gpu_context::submission_slots));
}
}  // namespace

void device_timer::record_begin(VkCommandBuffer cb, std::uint64_t ticket) const {
  if (!available()) return;
  vkCmdResetQueryPool(cb, pool_.get(), first_query(ticket), 2);
  vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool_.get(), first_query(ticket));
}

void device_timer::record_end(VkCommandBuffer cb, std::uint64_t ticket) const {
  if (available())
    vkCmdWriteTimestamp(cb, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool_.get(),
                        first_query(ticket) + 1);
}

double device_timer::seconds(std::uint64_t ticket) const {
  if (!available()) return 0;
  std::uint64_t ticks[2] = {0, 0};
  vk_check(
      vkGetQueryPoolResults(ctx_.vk(), pool_.get(), first_query(ticket), 2, sizeof ticks, ticks,
                            sizeof ticks[0], VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
      "vkGetQueryPoolResults");
  // A submission's first timestamp is written as soon as it reaches the queue, which may be while
  // the one before it still runs: its time starts when that one ended, so overlapping
  // submissions are not counted twice.
  const std::uint64_t elapsed = (ticks[1] - ticks[0]) & mask_;
  const std::uint64_t since_last = (ticks[1] - last_end_) & mask_;
  last_end_ = ticks[1];
  return double(std::min(elapsed, since_last)) * period_ns_ * 1e-9;
}

}  // namespace rtvk::gpu
