#include "merge.h"

#include <algorithm>
#include <climits>

#include "errors.h"
#include "format.h"

namespace rtvk {
namespace {

std::string describe(const render_window& w) {
  return "pixels " + std::to_string(w.x) + "," + std::to_string(w.y) + "," +
         std::to_string(w.width) + "," + std::to_string(w.height) + " samples " +
         std::to_string(w.sample_begin) + ":" + std::to_string(w.sample_end);
}

bool overlap(const render_window& a, const render_window& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
         b.y < a.y + a.height && a.sample_begin < b.sample_end && b.sample_begin < a.sample_end;
}

void check_compatible(const std::vector<named_partial>& parts) {
  if (parts.empty()) throw usage_error("merge: no parts given");
  const named_partial& first = parts.front();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const named_partial& p = parts[i];
    if (p.image.image_width != first.image.image_width ||
        p.image.image_height != first.image.image_height)
      throw usage_error(p.file + ": image is " + std::to_string(p.image.image_width) + "x" +
                        std::to_string(p.image.image_height) + " but " + first.file + "'s is " +
                        std::to_string(first.image.image_width) + "x" +
                        std::to_string(first.image.image_height));
    if (p.image.fingerprint != first.image.fingerprint || p.image.gamma != first.image.gamma)
      throw usage_error(p.file + ": rendered from a different scene, camera, frame or settings " +
                        "than " + first.file + " (fingerprint " + p.image.fingerprint + " vs " +
                        first.image.fingerprint + ")");
    for (std::size_t k = 0; k < i; ++k)
      if (overlap(p.image.window, parts[k].image.window))
        throw usage_error(p.file + " (" + describe(p.image.window) + ") and " + parts[k].file +
                          " (" + describe(parts[k].image.window) +
                          ") hold the same samples of "
                          "some pixels");
  }
}

}  // namespace

merged_render merge_partials(const std::vector<named_partial>& parts) {
  check_compatible(parts);
  const int width = parts.front().image.image_width, height = parts.front().image.image_height;
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  std::vector<color> sum(pixels, color(0));
  std::vector<int> count(pixels, 0), begin(pixels, INT_MAX), end(pixels, INT_MIN);
  for (const named_partial& part : parts) {
    const render_window& w = part.image.window;
    const float* rgb = part.image.rgb.data();
    for (int y = w.y; y < w.y + w.height; ++y)
      for (int x = w.x; x < w.x + w.width; ++x, rgb += 3) {
        const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
        sum[i] += color(rgb[0], rgb[1], rgb[2]) * double(w.samples());
        count[i] += w.samples();
        begin[i] = std::min(begin[i], w.sample_begin);
        end[i] = std::max(end[i], w.sample_end);
      }
  }
  merged_render out{framebuffer(width, height), parts.front().image};
  out.summary.rgb.clear();
  out.summary.window = {0, 0, width, height, begin[0], end[0]};
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::string where = "pixel " + std::to_string(i % std::size_t(width)) + "," +
                              std::to_string(i / std::size_t(width));
    if (count[i] == 0) throw usage_error("merge: " + where + " is in none of the parts");
    if (begin[i] != begin[0] || end[i] != end[0])
      throw usage_error("merge: the parts give " + where + " samples " + std::to_string(begin[i]) +
                        ":" + std::to_string(end[i]) + " but pixel 0,0 samples " +
                        std::to_string(begin[0]) + ":" + std::to_string(end[0]));
    if (count[i] != end[i] - begin[i])
      throw usage_error("merge: the parts hold " + std::to_string(count[i]) + " of samples " +
                        std::to_string(begin[i]) + ":" + std::to_string(end[i]) + " of " + where +
                        " (a sample range is missing)");
    // A true division: a pixel from one piece gets back exactly its stored value.
    out.fb.at(int(i % std::size_t(width)), int(i / std::size_t(width))) = sum[i] / double(count[i]);
  }
  return out;
}

}  // namespace rtvk
