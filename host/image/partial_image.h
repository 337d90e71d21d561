#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "aov_image.h"
#include "framebuffer.h"
#include "render_settings.h"

namespace rtvk {

// A piece of a render in linear float, as `rtvk render -o piece.exr` writes it and `rtvk merge`
// reads it: an OpenEXR file whose display window is the whole image, whose data window is the
// piece's rectangle, and whose header carries the sample range and what was rendered.
struct partial_image {
  int image_width = 0;      // the whole image, pixels
  int image_height = 0;     // the whole image, pixels
  render_window window;     // the rectangle (data window) and sample range this piece holds
  std::vector<float> rgb;   // window.width * window.height * 3: the mean linear color of the
                            // window's samples, row-major from the window's top row
  double gamma = 1;         // how to encode the merged image for PNG or PPM
  std::string fingerprint;  // the scene, settings and camera pose, hashed: only pieces with
                            // equal fingerprints merge
  std::string scene;        // scene name, for people reading the header
  std::string camera;       // camera name
  int frame = 0;            // animation frame
  std::string version;      // the rtvk that rendered it (version_string; empty in pieces of
                            // earlier rtvk): pieces of different versions do not merge unasked
  std::string shader;       // identity of the render shader (hash of its SPIR-V), likewise
  // With gamma, how the merged image is encoded for PNG or PPM; the pixels above never have
  // the exposure or the transform applied (scene-linear). Pieces of earlier rtvk: gamma, 0 EV.
  view_transform transform = view_transform::gamma;
  double exposure = 0;  // EV

  display_encoding encoding() const { return {transform, gamma, exposure}; }
};

// `header` (every field but rgb) with the pixels of `fb`, which is header.window.width x
// header.window.height, rounded to float.
partial_image make_partial(const framebuffer& fb, partial_image header);

// Writes atomically (never a partial file at `path`). Throws std::runtime_error on failure.
// `aovs` (the window's, when given): their channels beside R, G and B.
void write_partial_exr(const partial_image& p, const std::filesystem::path& path,
                       const aov_image* aovs = nullptr);

// One AOV of `a` alone, in an OpenEXR file of the image's size holding the window (the AOVs of a
// PNG or PPM render: out.png -> out.depth.exr, ...). Atomic, like write_partial_exr.
void write_aov_exr(const aov_image& a, aov_bit which, int image_width, int image_height,
                   const render_window& window, const std::filesystem::path& path);

// Throws image_read_error naming the file when it is not a regular file, cannot be read, is not
// OpenEXR, lacks rtvk's header attributes, or claims a data window whose pixels would not fit in
// the memory available (checked from the header, before anything is allocated for them).
partial_image read_partial_exr(const std::filesystem::path& path);

// 16 hex digits identifying a render's inputs from a canonical text of them.
std::string fingerprint_of(const std::string& canonical_text);

}  // namespace rtvk
