#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "environment.h"

namespace rtvk {

// An environment map's texels as both backends read them (shaders/shared/lights/environment.h):
// Radiance RGBE words, row by row from the top of the image.
struct environment_image {
  int width = 0;                      // texels in a row
  int height = 0;                     // rows
  std::vector<std::uint32_t> texels;  // RGBE, width x height
};

// What escaping rays see instead of the sky (scene files' "environment", --environment).
struct environment_map {
  std::string file;                                // as the scene file or the flag names it
  std::shared_ptr<const environment_image> image;  // never null in a scene
  double rotation = 0;                             // degrees about +y (docs/lighting.md)
  double strength = 1;                             // multiplies every texel's radiance, >= 0
  bool visible = true;  // camera rays that escape see it; false: they see the scene's sky
};

// The device limit an environment map is held to: lavapipe's storage-buffer range, 128 MiB, for
// its texels (4 bytes each) and for its sampling table (4 bytes an entry: (width + 2) x height +
// 9). 6144x3072 fits; 8192x4096 does not (its table is 20 KiB over).
inline constexpr std::uint64_t max_environment_buffer_bytes = std::uint64_t(128) << 20;
// The largest environment file read, bytes.
inline constexpr std::uint64_t max_environment_file_bytes = std::uint64_t(1) << 30;

// Radiance's RGBE word of a linear RGB texel (finite, >= 0): bits 0-23 the channels' mantissas,
// 24-31 the shared exponent; 0 (black) where the largest channel is below 2^-118. What a
// Radiance file decodes to (stb_image's float) encodes back exactly.
std::uint32_t encode_rgbe(float r, float g, float b);

// An environment image from linear float RGB, row by row from the top. Throws usage_error,
// naming `where`, for a texel that is not finite or is negative, or an image past the limit.
std::shared_ptr<const environment_image> environment_from_rgb(int width, int height,
                                                              const std::vector<float>& rgb,
                                                              const std::string& where);

// Reads a Radiance .hdr (stb_image) or OpenEXR .exr file (told apart by content) as an
// environment image. Throws usage_error naming `name` (the field or flag) and the file: missing,
// unreadable, not an HDR image, truncated, with a texel not finite or negative, or too large.
std::shared_ptr<const environment_image> load_environment_image(const std::filesystem::path& file,
                                                                const std::string& name);

// The same for a file's bytes (the fuzzer's entry); `where` leads every message.
std::shared_ptr<const environment_image> decode_environment_image(const std::string& bytes,
                                                                  const std::string& where);

// The map's sampling table (environment.h's layout): its header (size, strength, rotation,
// visibility, the sampler's loop trips) and the CDFs of luminance x sin(theta), in float, exactly
// as the GPU gets it.
std::vector<float> environment_table_of(const environment_map& e);

// The map packed for the C++ kernels: its texels and its table, and the view of both they take.
struct environment_tables {
  explicit environment_tables(const environment_map& e)
      : image(e.image), table(environment_table_of(e)) {}
  std::shared_ptr<const environment_image> image;
  std::vector<float> table;
  environment_table view() const { return {image->texels.data(), table.data()}; }
};

}  // namespace rtvk
