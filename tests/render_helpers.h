#pragma once
#include <algorithm>
#include <string>
// Short ways for tests to render a scene with its own settings on either backend.
#include "camera.h"
#include "image_compare.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_gpu.h"
#include "scene.h"

namespace rtvk::test {

inline camera scene_camera(const scene& s) {
  return camera(main_camera(s).pose, s.render.aspect, s.render.width);
}

inline image_rgb8 cpu_image(const scene& s, const camera& cam) {
  return quantize(render_cpu(cam, s, s.render), s.render.encoding());
}
inline image_rgb8 cpu_image(const scene& s) {
  return cpu_image(s, scene_camera(s));
}

inline image_rgb8 gpu_image(gpu::gpu_context& ctx, const scene& s, const camera& cam) {
  return quantize(gpu::render_gpu(ctx, cam, s, s.render), s.render.encoding());
}
inline image_rgb8 gpu_image(gpu::gpu_context& ctx, const scene& s) {
  return gpu_image(ctx, s, scene_camera(s));
}

// A built-in scene made small for tests: `width` pixels wide, at most `max_spp` samples.
inline scene small_scene(const std::string& name, int width, int max_spp) {
  scene s = builtin_scene(name);
  s.render.width = width;
  s.render.spp = std::min(s.render.spp, max_spp);
  return s;
}

// What a CPU-vs-GPU comparison measured on lavapipe (Mesa 22.3.6 and 25.0.7 draw the same
// images), less a stated margin: 3 dB of PSNR, and twice the share of pixels more than 2 levels
// off (at least one pixel of `pixels`). monte_carlo_agreement's 40 dB floor, the rule of rtvk
// render --backend both for any scene, would let a 20 dB regression of these through. The PSNR
// floor stops at 70 dB: images closer than that differ in a handful of pixels by a level, which
// another conformant device's rounding may change.
inline agreement measured_agreement(double psnr_db, double share, int pixels) {
  return {monte_carlo_agreement.tolerance, std::max(2 * share, 1.0 / pixels),
          std::min(psnr_db - 3, 70.0)};
}

// Whether two framebuffers hold the same pixels, bit for bit.
inline bool same_pixels(const framebuffer& a, const framebuffer& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (a.at(x, y) != b.at(x, y)) return false;
  return true;
}

// The lesson's image: the seed scene through the lesson's camera.
inline image_rgb8 seed_image(double aspect, int width) {
  return cpu_image(builtin_scene("seed"), camera(aspect, width));
}

}  // namespace rtvk::test
