#pragma once
#include <string>
#include <vector>

#include "framebuffer.h"
#include "partial_image.h"

namespace rtvk {

// A piece and the file it came from, for messages.
struct named_partial {
  std::string file;
  partial_image image;
};

// The pieces of one render combined: every pixel's mean, weighted by each piece's sample count,
// in double. The result's window is the whole image and the pieces' common sample range.
struct merged_render {
  framebuffer fb;         // the whole image, linear
  partial_image summary;  // the pieces' header fields, with the whole image's window (rgb empty)
};

// Combines pieces one at a time, so a merge of many full-image sample ranges holds one piece in
// memory, not all of them. add() throws usage_error, naming the files, for a piece of another
// render (image size, fingerprint or gamma) or one holding samples of some pixel that an earlier
// piece holds, or (unless allowed) for one rendered by another rtvk version; finish() throws
// usage_error when the pieces leave pixels or samples out: every pixel must end up with the same,
// gap-free range of samples.
class render_merger {
 public:
  // With `allow_mixed_versions`, pieces rendered by different rtvk versions or shaders merge;
  // without it, add() refuses them.
  explicit render_merger(bool allow_mixed_versions = false)
      : allow_mixed_versions_(allow_mixed_versions) {}
  void add(const std::string& file, const partial_image& piece);
  merged_render finish() const;

 private:
  struct seen {
    std::string file;      // for messages
    render_window window;  // what it held
  };
  partial_image first_;           // the first piece's header fields (no pixels)
  std::string first_file_;        // and its file
  std::vector<seen> seen_;        // every piece so far
  std::vector<color> sum_;        // per pixel: sum of mean * samples
  std::vector<int> count_;        // per pixel: samples added
  std::vector<int> begin_, end_;  // per pixel: smallest and largest sample index bound
  bool allow_mixed_versions_;     // pieces of different rtvk versions may merge
};

// All of `parts` through a render_merger.
merged_render merge_partials(const std::vector<named_partial>& parts,
                             bool allow_mixed_versions = false);

}  // namespace rtvk
