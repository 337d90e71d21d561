#pragma once
// How many samples the viewer's next pass adds, and where it stops. Kept apart from the window
// loop so that a test can start it anywhere, near the bound included, without a window.
#include <algorithm>

#include "render_settings.h"

namespace rtvk::view {

// The samples per pixel a session accumulates at most: its target, or max_spp (2^20) when it has
// none (target 0: "forever") or a larger one. The exact sums hold max_spp samples and
// tonemap.comp's 64-bit product of a sum and its threshold assumes no more, so past the bound
// the viewer stops accumulating and keeps showing the image: at 2^20 samples a pixel's mean is
// within a thousandth of a standard deviation of a sample of its value, far below one step
// of 8 bits for any pixel that is not mostly fireflies, so more samples would not change what
// is shown. A wider sum would cost every sample a wider add and the encoder a wider product.
inline int sample_cap(int target_spp) {
  return target_spp <= 0 ? max_spp : std::min(target_spp, max_spp);
}

// The samples of the next pass, given the samples `done` and a batch of `batch`: the batch, or
// what is left up to the cap; 0 once there.
inline int next_pass_samples(int target_spp, int done, int batch) {
  return std::max(0, std::min(batch, sample_cap(target_spp) - done));
}

}  // namespace rtvk::view
