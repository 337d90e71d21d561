#pragma once
// The statistics the unbiasedness tests compare modes by: an image's mean over renders at many
// seeds, with its standard error, and how far one render's pixels lie from a reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "render_cpu.h"
#include "render_helpers.h"
#include "scene.h"

namespace rtvk::test {

struct seed_estimate {
  color mean{0};   // each channel's image mean, over the seeds
  color error{0};  // its standard error
  double rms = 0;  // root-mean-square difference of a render's pixels from the reference, if any
};

// Renders s on the CPU at `runs` seeds from first_seed (its own settings otherwise).
inline seed_estimate over_seeds(scene s, int runs, std::uint32_t first_seed,
                                const framebuffer* reference = nullptr) {
  const camera cam = scene_camera(s);
  std::vector<color> means;
  double squares = 0;
  for (int k = 0; k < runs; ++k) {
    s.render.seed = first_seed + std::uint32_t(k);
    const framebuffer fb = render_cpu(cam, s, s.render);
    color m(0);
    for (int y = 0; y < fb.height(); ++y)
      for (int x = 0; x < fb.width(); ++x) {
        m += fb.at(x, y);
        if (reference) {
          const color d = fb.at(x, y) - reference->at(x, y);
          squares += (d.x * d.x + d.y * d.y + d.z * d.z) / 3;
        }
      }
    means.push_back(m / double(fb.width() * fb.height()));
  }
  seed_estimate out;
  for (const color& m : means) out.mean += m / double(runs);
  for (const color& m : means) out.error += (m - out.mean) * (m - out.mean);
  for (int c = 0; c < 3; ++c) out.error[c] = std::sqrt(out.error[c] / (runs - 1) / runs);
  const double pixels = double(cam.image_width()) * double(cam.image_height());
  out.rms = std::sqrt(squares / (pixels * runs));
  return out;
}

// Each channel of a's mean within 4 standard errors (of their difference) of b's: two estimators
// of one image agree (with 16 or more seeds each, Student's t stays near the normal's 4 sigma).
inline void expect_same_means(const seed_estimate& a, const std::string& a_name,
                              const seed_estimate& b, const std::string& b_name,
                              const std::string& where = "") {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(a.mean[c], b.mean[c], 4 * std::hypot(a.error[c], b.error[c]))
        << where << "channel " << c << ": " << b_name << " " << b.mean[c] << " +- " << b.error[c]
        << ", " << a_name << " " << a.mean[c] << " +- " << a.error[c];
}

}  // namespace rtvk::test
