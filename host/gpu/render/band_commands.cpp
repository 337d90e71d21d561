#include "band_commands.h"

#include <cstddef>

#include "packing.h"

namespace rtvk::gpu {

static_assert(band_slots == gpu_context::submission_slots);

void barrier(VkCommandBuffer cb, VkPipelineStageFlags src_stage, VkAccessFlags src,
             VkPipelineStageFlags dst_stage, VkAccessFlags dst) {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = src;
  b.dstAccessMask = dst;
  vkCmdPipelineBarrier(cb, src_stage, dst_stage, 0, 1, &b, 0, nullptr, 0, nullptr);
}

void record_tonemap(VkCommandBuffer cb, const compute_pipeline& tonemap, VkDeviceSize first,
                    VkDeviceSize pixels, const device_info& dev, tonemap_push style) {
  const VkDeviceSize groups = (pixels + 63) / 64;
  if (groups == 0) return;
  const VkDeviceSize row = std::min<VkDeviceSize>(groups, dev.limits.maxComputeWorkGroupCount[0]);
  tonemap.bind(cb);
  style.first = std::uint32_t(first);
  style.pixels = std::uint32_t(pixels);
  style.row_invocations = std::uint32_t(row * 64);
  tonemap.push(cb, &style, sizeof style);
  tonemap.dispatch(cb, {std::uint32_t(row), std::uint32_t((groups + row - 1) / row), 1});
}

void band_commands::set_views(const std::vector<camera>& views, std::size_t first,
                              std::uint32_t count) {
  cameras_.resize(count);
  for (std::uint32_t v = 0; v < count; ++v) cameras_[v] = to_ubo(views[first + v]);
}

// lavapipe compiles a pipeline's shaders in the first submission that runs it, which waits for
// that up to gpu_context::first_run_allowance beyond --gpu-timeout: a run of no work in a
// submission of its own takes the compile, so that the render's first submission (the pacer's
// calibration, pacer.h) holds to --gpu-timeout, and its measured time is its work's alone.
void band_commands::run_empty_first() {
  if (pipeline_.bound() || !pipeline_.has_empty_run() || !compiles_in_first_run(d_.ctx.device()))
    return;
  d_.ctx.submit_and_wait([&](VkCommandBuffer cb) {
    pipeline_.bind(cb);
    pipeline_.push(cb, &push_, sizeof push_);  // whatever it holds: no invocation reads it
    pipeline_.record_empty_run(cb);
  });
}

band_ticket band_commands::submit(const band_submission& s) {
  run_empty_first();
  push_.band_y0 = s.band->y0;
  push_.band_rows = s.band->rows;
  push_.sums_row0 = kept_ ? s.band->y0 : 0;
  push_.loop_budget = s.loop_budget;
  push_.trace_cost = s.trace_cost;
  push_.probe_trips = s.probe_trips;
  std::uint32_t dispatches = 0;
  const std::uint64_t ticket =
      d_.ctx.submit([&](VkCommandBuffer cb) { dispatches = record(cb, s); });
  d_.drawn = true;
  return {ticket, dispatches};
}

render_status band_commands::status(std::uint32_t slot) {
  return *static_cast<const render_status*>(d_.targets.status_readback(slot).read());
}

// Before a band's first samples: cleared sums and status.
void band_commands::record_start(VkCommandBuffer cb) const {
  if (d_.drawn) {  // the previous band's shader writes and copies out of these buffers come first
    barrier(cb, compute_stage_ | transfer_stage,
            shader_rw | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_WRITE_BIT);
  }
  // The group's cameras, in the command stream (no host-visible memory for the shader to
  // read; 16 KiB at most, within vkCmdUpdateBuffer's 64 KiB).
  vkCmdUpdateBuffer(cb, d_.targets.cameras.get(), 0, cameras_.size() * sizeof(camera_ubo),
                    cameras_.data());
  // Cleared for every band: a starved count is the band's to act on (the budget it raised
  // carries over in the pacer).
  vkCmdFillBuffer(cb, d_.targets.status.get(), 0, VK_WHOLE_SIZE, 0);
  if (!kept_) {
    vkCmdFillBuffer(cb, d_.targets.sums.get(), 0, VK_WHOLE_SIZE, 0);
  } else if (target_base_ == 0) {  // the band's rows of the image start afresh
    const VkDeviceSize row_bytes = VkDeviceSize(width_) * sizeof(pixel_sum);
    vkCmdFillBuffer(cb, d_.targets.sums.get(), push_.band_y0 * row_bytes,
                    push_.band_rows * row_bytes, 0);
  }
  barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage_,
          shader_rw | VK_ACCESS_UNIFORM_READ_BIT);
}

// After a band's last samples: the sums, or the bytes tonemap.comp makes of them, copied to
// host-visible memory.
void band_commands::record_readback(VkCommandBuffer cb, const band_pass& b) const {
  const VkDeviceSize pixels = VkDeviceSize(width_) * b.pixels();
  const device_info& dev = d_.ctx.device();
  barrier(cb, compute_stage_, VK_ACCESS_SHADER_WRITE_BIT, compute_stage_ | transfer_stage,
          VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
  if (kept_) {  // encoded into the image's bytes, which stay for the viewer to show
    record_tonemap(cb, *tonemap_, VkDeviceSize(width_) * b.y0, pixels, dev, d_.tonemap_style);
    barrier(cb, compute_stage_, VK_ACCESS_SHADER_WRITE_BIT, compute_stage_ | transfer_stage,
            VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
    return;
  }
  VkBufferCopy copy{0, 0, pixels * sizeof(pixel_sum)};
  VkBuffer from = d_.targets.sums.get();
  if (tonemap_) {
    record_tonemap(cb, *tonemap_, 0, pixels, dev, d_.tonemap_style);
    barrier(cb, compute_stage_, VK_ACCESS_SHADER_WRITE_BIT, transfer_stage,
            VK_ACCESS_TRANSFER_READ_BIT);
    copy.size = pixels * 4;
    from = d_.targets.bytes.get();
  }
  vkCmdCopyBuffer(cb, from, d_.targets.readback.get(), 1, &copy);
  barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
          VK_ACCESS_HOST_READ_BIT);
}

// One submission: dispatches bringing every pixel from `s.from` up to `s.to` samples, `s.step`
// at a time. When it is the band's last, the unfinished count is cleared before the last
// dispatch (so it counts only that one) and the readback follows. Returns the dispatches
// recorded.
std::uint32_t band_commands::record(VkCommandBuffer cb, const band_submission& s) {
  const std::uint64_t ticket = d_.ctx.next_ticket();
  d_.timer.record_begin(cb, ticket);
  if (s.first) {
    record_start(cb);
  } else {  // the previous submission's samples are in the sums this one adds to (and a
            // catch-up pass copies into the readback again)
    barrier(cb, compute_stage_ | transfer_stage,
            VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
            compute_stage_ | transfer_stage, shader_rw | VK_ACCESS_TRANSFER_WRITE_BIT);
  }
  std::uint32_t t = s.from;
  std::uint32_t dispatches = 0;
  bool first_dispatch = true;
  do {
    t = std::min(s.to, t + s.step);
    if (!first_dispatch)  // it goes on from the sums the one before left
      barrier(cb, compute_stage_, VK_ACCESS_SHADER_WRITE_BIT, compute_stage_, shader_rw);
    first_dispatch = false;
    if (s.last && t == s.to) {
      barrier(cb, compute_stage_, shader_rw, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT);
      vkCmdFillBuffer(cb, d_.targets.status.get(), offsetof(render_status, unfinished_pixels),
                      sizeof(std::uint32_t), 0);
      barrier(cb, transfer_stage, VK_ACCESS_TRANSFER_WRITE_BIT, compute_stage_, shader_rw);
    }
    pipeline_.bind(cb);
    push_.sample_target = target_base_ + t;
    pipeline_.push(cb, &push_, sizeof push_);
    dispatches +=
        pipeline_.dispatch(cb, {(push_.region_width + d_.wg[0] - 1) / d_.wg[0],
                                (push_.band_rows + d_.wg[1] - 1) / d_.wg[1], s.band->views});
  } while (t < s.to);
  if (s.last) record_readback(cb, *s.band);
  // The status the shader counted on the device, copied out for the scheduler to read.
  barrier(cb, compute_stage_ | transfer_stage,
          VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer_stage,
          VK_ACCESS_TRANSFER_READ_BIT);
  const VkBufferCopy status{0, 0, sizeof(render_status)};
  vkCmdCopyBuffer(cb, d_.targets.status.get(), d_.targets.status_readback(s.slot).get(), 1,
                  &status);
  barrier(cb, compute_stage_ | transfer_stage,
          VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
          VK_ACCESS_HOST_READ_BIT);
  d_.timer.record_end(cb, ticket);
  return dispatches;
}

}  // namespace rtvk::gpu
