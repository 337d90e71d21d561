// The view transforms on the device (tonemap.comp, docs/color.md): every per-channel transform,
// at any exposure, is bit for bit the host's encode_sum of the same sums (the thresholds carry
// the curve); AgX, which mixes the channels, is the shared kernel in float, within a level of
// the host's double; and a render encoded on the device is the CPU's picture under each one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "byte_encoding.h"
#include "gpu_engine.h"
#include "gpu_fixture.h"
#include "image_compare.h"
#include "quantize.h"
#include "render_helpers.h"
#include "sample_sum.h"

namespace rtvk {
namespace {

class GpuViewTransform : public test::GpuTest {};

gpu::pixel_sum vt_pixel(exact_sum r, exact_sum g, exact_sum b, std::uint32_t n) {
  const auto w = [](exact_sum v) {
    return gpu::uvec2(std::uint32_t(v), std::uint32_t(std::uint64_t(v) >> 32));
  };
  const auto top = [](exact_sum v) { return std::uint32_t(v >> 64); };
  return {w(r), w(g), w(b), n, 0, top(r), top(g), top(b), 0};
}

std::array<std::uint8_t, 3> vt_bytes(std::uint32_t rgba) {
  return {std::uint8_t(rgba), std::uint8_t(rgba >> 8), std::uint8_t(rgba >> 16)};
}

TEST_F(GpuViewTransform, EveryPerChannelTransformIsTheHostsEncodingAtAnyExposure) {
  const scene s = test::small_scene("seed", 8, 1);
  gpu::gpu_engine engine(gpu(), s);
  const int f = engine.sum_exponent();
  std::mt19937_64 rng(7);
  for (view_transform t : {view_transform::standard, view_transform::filmic, view_transform::linear,
                           view_transform::gamma}) {
    // -16 EV: thresholds near 2^60, products with the sample count past 64 bits.
    for (double ev : {0.0, 2.5, -7.0, -16.0}) {
      SCOPED_TRACE(std::string(view_transform_name(t)) + " EV " + std::to_string(ev));
      const display_encoding e{t, 2.2, ev};
      const byte_thresholds th = make_byte_thresholds(e, f);
      std::vector<gpu::pixel_sum> sums;
      for (int k = 1; k < 256; k += 3)
        for (std::uint32_t n : {1u, 1000u, 1u << 20}) {
          const exact_sum at = exact_sum(th[k]) * n;
          sums.push_back(vt_pixel(at, at - 1, at + n - 1, n));
        }
      for (int i = 0; i < 3000; ++i) {
        const std::uint32_t n = 1 + std::uint32_t(rng() % (1u << 20));
        const auto any = [&] { return exact_sum(rng() % (th[255] + th[255] / 4)) * n + rng() % n; };
        sums.push_back(vt_pixel(any(), any(), any(), n));
      }
      const std::vector<std::uint32_t> rgba = engine.encode_sums(sums, e);
      ASSERT_EQ(rgba.size(), sums.size());
      int mismatches = 0;
      for (std::size_t i = 0; i < sums.size(); ++i) {
        const gpu::pixel_sum& p = sums[i];
        const std::array<std::uint8_t, 3> want = {encode_sum(gpu::red_sum(p), p.samples, th),
                                                  encode_sum(gpu::green_sum(p), p.samples, th),
                                                  encode_sum(gpu::blue_sum(p), p.samples, th)};
        if (vt_bytes(rgba[i]) != want && ++mismatches <= 3)
          ADD_FAILURE() << "pixel " << i << ": device " << std::hex << rgba[i];
      }
      EXPECT_EQ(mismatches, 0);
    }
  }
}

TEST_F(GpuViewTransform, AgxOnTheDeviceIsWithinALevelOfTheHosts) {
  const scene s = test::small_scene("seed", 8, 1);
  gpu::gpu_engine engine(gpu(), s);
  const int f = engine.sum_exponent();
  std::mt19937_64 rng(8);
  for (double ev : {0.0, 3.0}) {
    const display_encoding e{view_transform::agx, 1, ev};
    std::vector<gpu::pixel_sum> sums;
    for (int i = 0; i < 20000; ++i) {
      const std::uint32_t n = 1 + std::uint32_t(rng() % 4096);
      // Means from 2^-14 to 2^6 on a log scale: AgX's whole log2 range and past it.
      const auto any = [&] {
        const double mean = std::exp2(-14.0 + 20.0 * double(rng() % 100000) / 100000);
        return exact_sum(std::ldexp(mean, f)) * n;
      };
      sums.push_back(vt_pixel(any(), any(), any(), n));
    }
    sums.push_back(vt_pixel(0, 0, 0, 0));  // no samples: black
    const std::vector<std::uint32_t> rgba = engine.encode_sums(sums, e);
    int worst = 0, off = 0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
      const gpu::pixel_sum& p = sums[i];
      const std::array<std::uint8_t, 3> want =
          p.samples == 0 ? std::array<std::uint8_t, 3>{0, 0, 0}
                         : encode_color(sum_mean(gpu::red_sum(p), p.samples, f),
                                        sum_mean(gpu::green_sum(p), p.samples, f),
                                        sum_mean(gpu::blue_sum(p), p.samples, f), e);
      const std::array<std::uint8_t, 3> got = vt_bytes(rgba[i]);
      for (int k = 0; k < 3; ++k) {
        const int d = std::abs(int(got[k]) - int(want[k]));
        worst = std::max(worst, d);
        off += d != 0;
      }
    }
    std::printf("AgX at %+.0f EV: %d of %zu channels a level off the host's, at most %d\n", ev, off,
                3 * sums.size(), worst);
    EXPECT_LE(worst, 1);
    EXPECT_LT(off, int(3 * sums.size() / 50));  // float's rounding crosses a level rarely
  }
}

TEST_F(GpuViewTransform, ARenderEncodedOnTheDeviceIsTheCpusPictureUnderEachTransform) {
  scene s = test::small_scene("seed", 48, 1);  // one sample, no jitter: the CPU's within a level
  const camera cam = test::scene_camera(s);
  const render_window win = whole_render(cam.image_width(), cam.image_height(), 1);
  gpu::gpu_engine engine(gpu(), s);
  for (view_transform t : {view_transform::standard, view_transform::filmic, view_transform::agx,
                           view_transform::linear, view_transform::gamma}) {
    SCOPED_TRACE(view_transform_name(t));
    s.render.transform = t;
    s.render.exposure = 0.5;
    const image_rgb8 gpu_bytes = engine.render_encoded({cam}, s.render, win)[0];
    const image_difference d = compare_images(gpu_bytes, test::cpu_image(s, cam), 1);
    EXPECT_LE(d.max_abs, 1);
    // Not the picture of another transform.
    if (t != view_transform::standard) {
      scene other = s;
      other.render.transform = view_transform::standard;
      EXPECT_GT(compare_images(gpu_bytes, test::cpu_image(other, cam), 1).max_abs, 1);
    }
  }
}

}  // namespace
}  // namespace rtvk
