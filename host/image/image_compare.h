#pragma once
#include <cstdint>

#include "image_rgb8.h"

namespace rtvk {

// How two images of the same size differ. Differences are in 8-bit levels (0 to 255).
struct image_difference {
  int width = 0;                 // pixels
  int height = 0;                // pixels
  int max_abs = 0;               // largest channel difference
  double mean_abs = 0;           // mean channel difference
  double psnr_db = 0;            // peak signal-to-noise ratio; +inf when identical
  std::int64_t pixels_over = 0;  // pixels with some channel differing by more than the tolerance
  double share_over = 0;         // pixels_over / (width * height)
};

// When two renders count as the same picture: at most `max_share` of the pixels may have a
// channel more than `tolerance` levels off, and the PSNR is at least `min_psnr_db`. The defaults
// are the CPU/GPU rule for deterministic scenes (the lesson's): float rounding moves a channel by
// one level and may flip a few silhouette pixels.
struct agreement {
  int tolerance = 1;         // levels
  double max_share = 0.001;  // fraction of pixels, 0.1 %
  double min_psnr_db = 0;    // 0: not checked
};

// The CPU/GPU rule for Monte Carlo renders: both draw the same random numbers, but a path that
// float rounding sends another way changes a pixel's noise, not the picture.
inline constexpr agreement monte_carlo_agreement{2, 0.01, 40};

// Requires equal sizes (the caller checks).
image_difference compare_images(const image_rgb8& a, const image_rgb8& b, int tolerance);
bool agrees(const image_difference& d, const agreement& rule);

// A heat map of where a and b differ: black where equal, through red and yellow to white at a
// difference of 64 levels or more in the worst channel.
image_rgb8 difference_heatmap(const image_rgb8& a, const image_rgb8& b);

}  // namespace rtvk
