#pragma once
// What the viewer's accumulation needs beside the device's sums: how far each row is, and how
// large the next batch of work should be.
#include <algorithm>
#include <vector>

namespace rtvk::view {

// How far the accumulation is, row by row; the sums themselves and their encoding stay on the
// device (gpu_engine::accumulate). Batches cover bands of rows, so rows may briefly hold one
// pass more than others.
struct accumulation {
  int width = 0, height = 0;     // pixels
  int samples = 0;               // per pixel in every row: the passes completed
  std::vector<int> row_samples;  // per row, from the top

  void reset(int w, int h) {
    width = w;
    height = h;
    samples = 0;
    row_samples.assign(std::size_t(h), 0);
  }
  // Counts `count` samples more for rows [row, row + rows).
  void add(int row, int rows, int count) {
    for (int y = row; y < row + rows; ++y) row_samples[std::size_t(y)] += count;
    samples = *std::min_element(row_samples.begin(), row_samples.end());
  }
};

// A batch is `count` samples of a band of rows. Both adapt so that a batch takes about 60 ms,
// keeping the window above 10 frames a second on slow devices (lavapipe: bands of the image)
// and busy on fast ones (many samples of the whole image): bands grow to the whole image before
// samples grow past one, and samples shrink back to one before bands shrink.
struct batch_shape {
  int rows = 16;  // band height, pixels
  int count = 1;  // samples per pixel

  void adapt(double seconds, int height) {
    constexpr double target = 0.06;
    if (seconds < target / 2) {
      if (rows < height)
        rows = std::min(rows * 2, height);
      else
        count = std::min(count * 2, 1 << 16);
    } else if (seconds > target * 2) {
      if (count > 1)
        count /= 2;
      else
        rows = std::max(rows / 2, 1);
    }
  }
};

}  // namespace rtvk::view
