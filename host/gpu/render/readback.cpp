#include "readback.h"

#include <algorithm>

#include "parallel.h"

namespace rtvk::gpu {
namespace {

// Runs body(row) for rows [0, rows) on every core: readback conversion should not leave all but
// one idle.
void for_rows(int rows, const std::function<void(int row)>& body) {
  parallel_for(std::size_t(std::max(rows, 0)), 0, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t row = begin; row < end; ++row) body(int(row));
  });
}

// One image per view, each made in place: filling a vector with copies of one made first wrote
// every image twice (an H200 renders book-final's 1200x675 in 6 ms of device time, and copying
// its 19 MB framebuffer, page faults and all, cost about as much again).
template <typename Make>
auto one_per_view(std::size_t views, Make make) {
  std::vector<decltype(make())> out;
  out.reserve(views);
  for (std::size_t k = 0; k < views; ++k) out.push_back(make());
  return out;
}

}  // namespace

std::vector<framebuffer> framebuffers_for(std::size_t views, const render_window& win) {
  return one_per_view(views, [&] { return framebuffer{win.width, win.height}; });
}

band_sink means_into(std::vector<framebuffer>& out, int width, int exponent) {
  return [&out, width, exponent](std::size_t first, std::uint32_t count, int row0, int rows,
                                 const void* data) {
    const auto* sums = static_cast<const pixel_sum*>(data);
    const int f = exponent;
    for_rows(int(count) * rows, [&](int r) {
      framebuffer& fb = out[first + std::size_t(r / rows)];
      const pixel_sum* p = sums + std::size_t(r) * std::size_t(width);
      const int y = row0 + r % rows;
      for (int x = 0; x < width; ++x, ++p)
        fb.at(x, y) =
            color(sum_mean(red_sum(*p), p->samples, f), sum_mean(green_sum(*p), p->samples, f),
                  sum_mean(blue_sum(*p), p->samples, f));
    });
  };
}

std::vector<image_rgb8> images_for(std::size_t views, const render_window& win) {
  return one_per_view(views, [&] {
    return image_rgb8{
        win.width, win.height,
        std::vector<std::uint8_t>(std::size_t(win.width) * std::size_t(win.height) * 3)};
  });
}

band_sink bytes_into(std::vector<image_rgb8>& out, int width) {
  return
      [&out, width](std::size_t first, std::uint32_t count, int row0, int rows, const void* data) {
        const auto* rgba = static_cast<const std::uint8_t*>(data);
        for_rows(int(count) * rows, [&](int r) {
          image_rgb8& img = out[first + std::size_t(r / rows)];
          const std::uint8_t* from = rgba + std::size_t(r) * std::size_t(width) * 4;
          std::uint8_t* to = img.rgb.data() + std::size_t(row0 + r % rows) * width * 3;
          for (int x = 0; x < width; ++x, from += 4, to += 3) std::copy(from, from + 3, to);
        });
      };
}

std::vector<sum_image> sum_images_for(std::size_t views, const render_window& win, int exponent) {
  return one_per_view(views, [&] {
    return sum_image{win.width, win.height, exponent,
                     std::vector<pixel_sum>(std::size_t(win.width) * win.height)};
  });
}

band_sink sums_into(std::vector<sum_image>& out, int width) {
  return
      [&out, width](std::size_t first, std::uint32_t count, int row0, int rows, const void* data) {
        const auto* sums = static_cast<const pixel_sum*>(data);
        const std::size_t w = std::size_t(width);
        for (std::uint32_t v = 0; v < count; ++v)
          std::copy(sums + v * rows * w, sums + (v + 1) * rows * w,
                    out[first + v].pixels.begin() + std::ptrdiff_t(row0 * w));
      };
}

image_rgb8 rgb_of_rgba(const std::uint8_t* rgba, int width, int height) {
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  image_rgb8 out{width, height, std::vector<std::uint8_t>(pixels * 3)};
  for (std::size_t i = 0; i < pixels; ++i)
    std::copy(rgba + 4 * i, rgba + 4 * i + 3, out.rgb.begin() + std::ptrdiff_t(3 * i));
  return out;
}

}  // namespace rtvk::gpu
