#pragma once
// The Vulkan side of a band: the commands each submission records (clears, cameras, dispatches,
// barriers, the readback and the status copy), queued on the engine's context. The scheduler
// (band_scheduler.h) decides what each submission asks for.
#include <array>
#include <cstdint>
#include <vector>

#include "band_scheduler.h"
#include "camera.h"
#include "compute_pipeline.h"
#include "context.h"
#include "device_timer.h"
#include "render_targets.h"
#include "shared_types.h"

namespace rtvk::gpu {

inline constexpr VkPipelineStageFlags compute_stage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
inline constexpr VkPipelineStageFlags transfer_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
inline constexpr VkAccessFlags shader_rw = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;

// A global memory barrier from the source stages and accesses to the destination ones.
void barrier(VkCommandBuffer cb, VkPipelineStageFlags src_stage, VkAccessFlags src,
             VkPipelineStageFlags dst_stage, VkAccessFlags dst);

// tonemap.comp over `pixels` sums from pixel `first`: 64 a workgroup, in rows of workgroups
// within the device's workgroup count limit (and tiles of those rows, by
// compute_pipeline::dispatch).
// `style` holds the encoding's transform and mean scale (its other fields are set here).
void record_tonemap(VkCommandBuffer cb, const compute_pipeline& tonemap, VkDeviceSize first,
                    VkDeviceSize pixels, const device_info& dev, tonemap_push style);

// What band_commands uses of its engine. `drawn` (some band was drawn before) carries over from
// one render to the next.
struct band_device {
  gpu_context& ctx;
  render_targets& targets;
  const device_timer& timer;
  std::array<std::uint32_t, 2> wg;  // workgroup size
  bool& drawn;
  tonemap_push tonemap_style = {};  // the encoding's transform and mean scale
};

// The engine's band_queue. The last submission of a band ends with its readback (sums, or
// bytes encoded by `tonemap`). A band `kept` on the device (the viewer's accumulation) goes on
// from the sums the image's buffer holds for its rows (every pixel at `target_base` samples;
// cleared first when that is 0), and ends with those rows encoded into the image's bytes, not
// read back.
class band_commands : public band_queue {
 public:
  band_commands(const band_device& device, const shader_program& pipeline,
                const compute_pipeline* tonemap, const render_push& push, std::uint32_t width,
                bool kept, std::uint32_t target_base)
      : d_(device),
        pipeline_(pipeline),
        tonemap_(tonemap),
        push_(push),
        width_(width),
        kept_(kept),
        target_base_(target_base),
        compute_stage_(compute_stage | pipeline.stages()) {}

  // The cameras of the views the next bands draw (written into the command stream).
  void set_views(const std::vector<camera>& views, std::size_t first, std::uint32_t count);

  band_ticket submit(const band_submission& s) override;
  void wait(std::uint64_t ticket) override { d_.ctx.wait(ticket); }
  void wait_all() noexcept override { d_.ctx.wait_all(); }
  bool has_timer() const override { return d_.timer.available(); }
  double device_seconds(std::uint64_t ticket) const override { return d_.timer.seconds(ticket); }
  render_status status(std::uint32_t slot) override;
  std::string device_name() const override { return d_.ctx.device().name; }

 private:
  void run_empty_first();
  std::uint32_t record(VkCommandBuffer cb, const band_submission& s);
  void record_start(VkCommandBuffer cb) const;
  void record_readback(VkCommandBuffer cb, const band_pass& b) const;

  band_device d_;
  const shader_program& pipeline_;
  const compute_pipeline* tonemap_;  // encodes the readback to bytes; null: sums
  render_push push_;                 // band and target fields change per dispatch
  std::uint32_t width_;              // of the window, pixels
  std::vector<camera_ubo> cameras_;  // of the views the bands draw (set_views)
  bool kept_;                        // the image's sums stay on the device (the viewer's)
  std::uint32_t target_base_;        // samples the kept sums already hold; 0 otherwise
  // The stages the render's shaders run in: compute (tonemap.comp, and render.comp or
  // render_query.comp) and the ray-tracing pipeline's, for barriers.
  VkPipelineStageFlags compute_stage_;
};

}  // namespace rtvk::gpu
