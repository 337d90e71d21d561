#pragma once
#include <cstdint>

#include "byte_encoding.h"

namespace rtvk {

// How paths pick their directions at diffuse surfaces and in media (docs/sampling.md).
enum class sampling_mode : std::uint8_t {
  automatic,  // `lights` where the scene has lights to aim at, else `plain`
  plain,      // the first two books': each material's own scattering
  lights,     // the third book's: half toward the lights, weighted by the mixture's density,
              // and stratified pixel samples
  nee,        // next-event estimation: a light sample and a shadow ray at every diffuse or PBR
              // vertex, weighed against the BSDF's sample by multiple importance sampling, and
              // stratified pixel samples (shaders/shared/lights/nee.h)
};

// How to render a scene: what a scene file's "render" object holds, and what the CLI overrides.
struct render_settings {
  int width = 400;             // image width, pixels
  double aspect = 16.0 / 9.0;  // image width / height
  int spp = 1;                 // samples per pixel
  int max_depth = 50;          // most scatter events a path may take
  std::uint32_t seed = 0;      // random number seed: same seed, same image
  double gamma = 1;            // the power law's: 1 linear (the lesson), 2 the book's sqrt
  // How 8-bit images encode the scene-linear means (docs/color.md): the built-in scenes keep
  // the books' power law; mesh files and scene files without "gamma" get standard (sRGB).
  view_transform transform = view_transform::gamma;
  double exposure = 0;  // EV: means times 2^exposure before the transform (not in .exr)
  bool jitter = false;  // random sample positions inside each pixel (antialiasing)
  sampling_mode sampling = sampling_mode::automatic;  // --sampling, "sampling"

  display_encoding encoding() const { return {transform, gamma, exposure}; }
};

// The part of a render that one run draws: a rectangle of the image and a range of each pixel's
// sample indices. Every pixel's random numbers depend only on (seed, pixel, sample, ...), so
// pieces drawn apart -- on other machines -- and merged equal the whole render.
struct render_window {
  int x = 0;             // left column, pixels from the image's left edge
  int y = 0;             // top row, pixels from the image's top edge
  int width = 0;         // pixels
  int height = 0;        // pixels
  int sample_begin = 0;  // first sample index drawn
  int sample_end = 0;    // one past the last sample index drawn

  int samples() const { return sample_end - sample_begin; }
  bool operator==(const render_window&) const = default;
};

// The whole image, every sample.
inline render_window whole_render(int image_width, int image_height, int spp) {
  return {0, 0, image_width, image_height, 0, spp};
}

// Throws std::invalid_argument unless `win` lies inside a width x height image and draws at least
// one sample.
void check_window(const render_window& win, int width, int height);

inline constexpr int max_spp = 1 << 20;        // samples per pixel
inline constexpr int max_depth_limit = 10000;  // bounces

}  // namespace rtvk
