#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace rtvk {
namespace {

int worst_channel(const image_rgb8& a, const image_rgb8& b, std::size_t i) {
  int worst = 0;
  for (int c = 0; c < 3; ++c)
    worst = std::max(worst, std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])));
  return worst;
}

}  // namespace

image_difference compare_images(const image_rgb8& a, const image_rgb8& b, int tolerance) {
  image_difference d;
  d.width = a.width;
  d.height = a.height;
  double sum = 0, sum_sq = 0;
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c]));
      sum += diff;
      sum_sq += double(diff) * diff;
      worst = std::max(worst, diff);
    }
    d.max_abs = std::max(d.max_abs, worst);
    if (worst > tolerance) ++d.pixels_over;
  }
  const double channels = double(a.rgb.size());
  const double pixels = channels / 3;
  d.mean_abs = channels > 0 ? sum / channels : 0;
  d.share_over = pixels > 0 ? d.pixels_over / pixels : 0;
  const double mse = channels > 0 ? sum_sq / channels : 0;
  d.psnr_db =
      mse == 0 ? std::numeric_limits<double>::infinity() : 10 * std::log10(255.0 * 255.0 / mse);
  return d;
}

bool agrees(const image_difference& d, const agreement& rule) {
  return d.share_over <= rule.max_share && d.psnr_db >= rule.min_psnr_db;
}

image_rgb8 difference_heatmap(const image_rgb8& a, const image_rgb8& b) {
  image_rgb8 out{a.width, a.height, std::vector<std::uint8_t>(a.rgb.size())};
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    const double t = std::min(1.0, worst_channel(a, b, i) / 64.0);  // 0 equal, 1 far apart
    // black -> red -> yellow -> white in three equal steps
    out.rgb[i] = std::uint8_t(255 * std::clamp(3 * t, 0.0, 1.0));
    out.rgb[i + 1] = std::uint8_t(255 * std::clamp(3 * t - 1, 0.0, 1.0));
    out.rgb[i + 2] = std::uint8_t(255 * std::clamp(3 * t - 2, 0.0, 1.0));
  }
  return out;
}

}  // namespace rtvk
