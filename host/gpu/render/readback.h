#pragma once
// What a render reads back, apart from how it is drawn: a band's sums made into means, its
// bytes made into RGB, or its sums kept as the device left them; each a sink the engine calls
// once a band's readback is in host memory.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "framebuffer.h"
#include "image_rgb8.h"
#include "render_settings.h"
#include "sample_sum.h"
#include "shared_types.h"

namespace rtvk::gpu {

// A render's exact per-pixel sums as the device left them: the mean of a channel is
// sum_mean(sum, samples, exponent) (sample_sum.h). For encoders and for tests.
struct sum_image {
  int width = 0, height = 0;      // pixels of the window
  int exponent = 0;               // F: fractional bits of the sums
  std::vector<pixel_sum> pixels;  // row-major from the window's top
};

// A pixel's channel sums, as integers.
inline exact_sum red_sum(const pixel_sum& p) {
  return channel_sum(p.r.x, p.r.y, p.r_top);
}
inline exact_sum green_sum(const pixel_sum& p) {
  return channel_sum(p.g.x, p.g.y, p.g_top);
}
inline exact_sum blue_sum(const pixel_sum& p) {
  return channel_sum(p.b.x, p.b.y, p.b_top);
}

// What a render reads back: each band's sums, or its bytes encoded on the device; or nothing,
// the sums and bytes kept on the device (the viewer's accumulation).
enum class readback_kind { sums, bytes, kept };

// Called for each band once its readback is in host memory: the band's first view (index into
// the render's views), views, first row (from the window's top) and rows, and the data (for
// each view in turn, rows x window width pixel_sum or RGBA8).
using band_sink = std::function<void(std::size_t first_view, std::uint32_t views, int row, int rows,
                                     const void* data)>;

// One empty result per view of the window, and the sink that fills them: each pixel's mean (of
// sums with `exponent` fractional bits), its encoded bytes, or its sums.
std::vector<framebuffer> framebuffers_for(std::size_t views, const render_window& win);
band_sink means_into(std::vector<framebuffer>& out, int width, int exponent);
std::vector<image_rgb8> images_for(std::size_t views, const render_window& win);
band_sink bytes_into(std::vector<image_rgb8>& out, int width);
std::vector<sum_image> sum_images_for(std::size_t views, const render_window& win, int exponent);
band_sink sums_into(std::vector<sum_image>& out, int width);

// RGBA8 pixels (red in the low byte) as RGB: the viewer's screenshots.
image_rgb8 rgb_of_rgba(const std::uint8_t* rgba, int width, int height);

}  // namespace rtvk::gpu
