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

// Throws usage_error, naming the files, when the pieces are not of one render (different image
// size, fingerprint or gamma), when two of them hold the same samples of a pixel, or when the
// pieces leave pixels or samples out: every pixel must end up with the same, gap-free range of
// samples.
merged_render merge_partials(const std::vector<named_partial>& parts);

}  // namespace rtvk
