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

std::string build_of(const partial_image& p) {
  return (p.version.empty() ? "(unknown version)" : p.version) + " with shader " +
         (p.shader.empty() ? "(unknown)" : p.shader);
}

}  // namespace

void render_merger::add(const std::string& file, const partial_image& p) {
  if (seen_.empty()) {
    first_ = partial_image{p.image_width, p.image_height, p.window,  {},      p.gamma,
                           p.fingerprint, p.scene,        p.camera,  p.frame, p.version,
                           p.shader,      p.transform,    p.exposure};
    first_file_ = file;
    const std::size_t pixels = std::size_t(p.image_width) * std::size_t(p.image_height);
    sum_.assign(pixels, color(0));
    count_.assign(pixels, 0);
    begin_.assign(pixels, INT_MAX);
    end_.assign(pixels, INT_MIN);
  }
  if (p.image_width != first_.image_width || p.image_height != first_.image_height)
    throw usage_error(file + ": image is " + std::to_string(p.image_width) + "x" +
                      std::to_string(p.image_height) + " but " + first_file_ + "'s is " +
                      std::to_string(first_.image_width) + "x" +
                      std::to_string(first_.image_height));
  if (p.fingerprint != first_.fingerprint || p.encoding() != first_.encoding())
    throw usage_error(file + ": rendered from a different scene, camera, frame or settings " +
                      "than " + first_file_ + " (fingerprint " + p.fingerprint + " vs " +
                      first_.fingerprint + ")");
  if (!allow_mixed_versions_ && (p.version != first_.version || p.shader != first_.shader))
    throw usage_error(file + ": rendered by rtvk " + build_of(p) + " but " + first_file_ +
                      " by rtvk " + build_of(first_) +
                      " (their images may differ; --allow-mixed-versions merges them anyway)");
  const render_window& w = p.window;
  if (w.x < 0 || w.y < 0 || w.x + w.width > p.image_width || w.y + w.height > p.image_height ||
      p.rgb.size() != std::size_t(w.width) * std::size_t(w.height) * 3)
    throw usage_error(file + ": " + describe(w) + " does not fit its image");
  for (const seen& s : seen_)
    if (overlap(w, s.window))
      throw usage_error(file + " (" + describe(w) + ") and " + s.file + " (" + describe(s.window) +
                        ") hold the same samples of some pixels");
  seen_.push_back({file, w});
  const float* rgb = p.rgb.data();
  for (int y = w.y; y < w.y + w.height; ++y)
    for (int x = w.x; x < w.x + w.width; ++x, rgb += 3) {
      const std::size_t i = std::size_t(y) * std::size_t(p.image_width) + std::size_t(x);
      sum_[i] += color(rgb[0], rgb[1], rgb[2]) * double(w.samples());
      count_[i] += w.samples();
      begin_[i] = std::min(begin_[i], w.sample_begin);
      end_[i] = std::max(end_[i], w.sample_end);
    }
}

merged_render render_merger::finish() const {
  if (seen_.empty()) throw usage_error("merge: no parts given");
  const int width = first_.image_width, height = first_.image_height;
  merged_render out{framebuffer(width, height), first_};
  out.summary.window = {0, 0, width, height, begin_[0], end_[0]};
  for (std::size_t i = 0; i < count_.size(); ++i) {
    const std::string where = "pixel " + std::to_string(i % std::size_t(width)) + "," +
                              std::to_string(i / std::size_t(width));
    if (count_[i] == 0) throw usage_error("merge: " + where + " is in none of the parts");
    if (begin_[i] != begin_[0] || end_[i] != end_[0])
      throw usage_error("merge: the parts give " + where + " samples " + std::to_string(begin_[i]) +
                        ":" + std::to_string(end_[i]) + " but pixel 0,0 samples " +
                        std::to_string(begin_[0]) + ":" + std::to_string(end_[0]));
    if (count_[i] != end_[i] - begin_[i])
      throw usage_error("merge: the parts hold " + std::to_string(count_[i]) + " of samples " +
                        std::to_string(begin_[i]) + ":" + std::to_string(end_[i]) + " of " + where +
                        " (a sample range is missing)");
    // A true division: a pixel from one piece gets back exactly its stored value.
    out.fb.at(int(i % std::size_t(width)), int(i / std::size_t(width))) =
        sum_[i] / double(count_[i]);
  }
  return out;
}

merged_render merge_partials(const std::vector<named_partial>& parts, bool allow_mixed_versions) {
  render_merger m(allow_mixed_versions);
  for (const named_partial& p : parts) m.add(p.file, p.image);
  return m.finish();
}

}  // namespace rtvk
