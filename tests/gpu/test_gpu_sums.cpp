// Many samples per invocation, summed exactly: on one device a render's sums do not depend on
// how its samples were batched into dispatches and submissions, or on a loop budget that cuts
// invocations short; sample ranges add up to the whole; the bytes encoded on the device are the
// host's encode_sum of those sums; and a million samples do not drift from the CPU's mean.
#include <gtest/gtest.h>

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

class GpuSums : public test::GpuTest {};

std::string text(exact_sum s) {  // for messages
  std::string digits;
  do digits.insert(digits.begin(), char('0' + int(s % 10)));
  while ((s /= 10) != 0);
  return digits;
}

bool same_sums(const gpu::sum_image& a, const gpu::sum_image& b, std::string& why) {
  if (a.pixels.size() != b.pixels.size()) return why = "sizes differ", false;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const gpu::pixel_sum &p = a.pixels[i], &q = b.pixels[i];
    if (gpu::red_sum(p) != gpu::red_sum(q) || gpu::green_sum(p) != gpu::green_sum(q) ||
        gpu::blue_sum(p) != gpu::blue_sum(q) || p.samples != q.samples) {
      why = "pixel " + std::to_string(i) + ": red " + text(gpu::red_sum(p)) + " vs " +
            text(gpu::red_sum(q)) + ", samples " + std::to_string(p.samples) + " vs " +
            std::to_string(q.samples);
      return false;
    }
  }
  return true;
}

TEST_F(GpuSums, BatchingAndLoopBudgetsDoNotChangeASingleBit) {
  scene s = test::small_scene("book-final", 12, 48);  // jittered, glass and metal: noisy sums
  s.render.max_depth = 12;
  const camera cam = test::scene_camera(s);
  const render_window win = whole_render(cam.image_width(), cam.image_height(), 48);
  const auto sums = [&](gpu::gpu_render_options o) {
    return gpu::gpu_engine(gpu(), s, o).render_sums({cam}, s.render, win)[0];
  };
  const gpu::sum_image want = sums({.samples_per_dispatch = 1, .samples_per_submission = 1});
  for (const gpu::pixel_sum& p : want.pixels) ASSERT_EQ(p.samples, 48u);
  struct variant {
    const char* what;
    gpu::gpu_render_options options;
  };
  const std::vector<variant> variants{
      {"all 48 in one dispatch", {.samples_per_dispatch = 48, .samples_per_submission = 48}},
      {"5 per dispatch, 15 per submission",
       {.samples_per_dispatch = 5, .samples_per_submission = 15}},
      {"adapted sizes", {}},
      // About one sample per budget: most invocations stop early and go on in later dispatches.
      {"a loop budget of 400", {.loop_budget = 400, .samples_per_dispatch = 48}},
  };
  for (const variant& v : variants) {
    std::string why;
    EXPECT_TRUE(same_sums(sums(v.options), want, why)) << v.what << ": " << why;
  }
}

TEST_F(GpuSums, SampleRangesAddUpToTheWholeExactly) {
  const scene s = test::small_scene("book-final", 10, 40);
  const camera cam = test::scene_camera(s);
  const int w = cam.image_width(), h = cam.image_height();
  gpu::gpu_engine engine(gpu(), s);
  const gpu::sum_image whole = engine.render_sums({cam}, s.render, {0, 0, w, h, 0, 40})[0];
  const gpu::sum_image first = engine.render_sums({cam}, s.render, {0, 0, w, h, 0, 13})[0];
  const gpu::sum_image rest = engine.render_sums({cam}, s.render, {0, 0, w, h, 13, 40})[0];
  for (std::size_t i = 0; i < whole.pixels.size(); ++i) {
    EXPECT_TRUE(gpu::green_sum(first.pixels[i]) + gpu::green_sum(rest.pixels[i]) ==
                gpu::green_sum(whole.pixels[i]))
        << i;
    EXPECT_EQ(first.pixels[i].samples + rest.pixels[i].samples, 40u) << i;
  }
}

TEST_F(GpuSums, BytesEncodedOnTheDeviceAreTheHostsEncodingOfTheSameSums) {
  for (const char* name : {"book-final", "seed", "materials"}) {
    SCOPED_TRACE(name);
    const scene s = test::small_scene(name, 40, 6);
    const camera cam = test::scene_camera(s);
    const render_window win = whole_render(cam.image_width(), cam.image_height(), s.render.spp);
    gpu::gpu_engine engine(gpu(), s);
    const gpu::sum_image sums = engine.render_sums({cam}, s.render, win)[0];
    const image_rgb8 bytes = engine.render_encoded({cam}, s.render, win)[0];
    const byte_thresholds t = make_byte_thresholds(s.render.gamma, sums.exponent);
    ASSERT_EQ(bytes.rgb.size(), sums.pixels.size() * 3);
    int mismatches = 0;
    for (std::size_t i = 0; i < sums.pixels.size(); ++i) {
      const gpu::pixel_sum& p = sums.pixels[i];
      const std::uint8_t want[3] = {encode_sum(gpu::red_sum(p), p.samples, t),
                                    encode_sum(gpu::green_sum(p), p.samples, t),
                                    encode_sum(gpu::blue_sum(p), p.samples, t)};
      for (int k = 0; k < 3; ++k) mismatches += bytes.rgb[3 * i + k] != want[k];
    }
    EXPECT_EQ(mismatches, 0);
    // And the same picture as quantizing the means on the host, the way the CPU's is written.
    const image_difference d = compare_images(
        bytes, quantize(engine.render_views({cam}, s.render, win)[0], s.render.gamma), 0);
    EXPECT_EQ(d.max_abs, 0);
  }
}

TEST_F(GpuSums, TheDevicesEncodingIsTheHostsAtEveryThreshold) {
  // Sums exactly at each byte's threshold, one below it, and random ones, for sample counts up
  // to 2^20: where an off-by-one comparison or a rounded division would show.
  const scene s = test::small_scene("seed", 8, 1);
  gpu::gpu_engine engine(gpu(), s);
  const int f = engine.sum_exponent();
  std::mt19937_64 rng(99);
  for (double gamma : {1.0, 2.0, 2.2}) {
    SCOPED_TRACE("gamma " + std::to_string(gamma));
    const byte_thresholds t = make_byte_thresholds(gamma, f);
    std::vector<gpu::pixel_sum> sums;
    const auto add = [&](exact_sum r, exact_sum g, exact_sum b, std::uint32_t n) {
      const auto w = [](exact_sum v) {
        return gpu::uvec2(std::uint32_t(v), std::uint32_t(std::uint64_t(v) >> 32));
      };
      const auto top = [](exact_sum v) { return std::uint32_t(v >> 64); };
      sums.push_back({w(r), w(g), w(b), n, 0, top(r), top(g), top(b), 0});
    };
    for (int k = 1; k < 256; ++k)
      for (std::uint32_t n : {1u, 3u, 1000u, 1u << 20}) {
        const std::uint64_t at = t[k] * n;
        add(at, at - 1, at + n - 1, n);
      }
    for (int i = 0; i < 4000; ++i) {
      const std::uint32_t n = 1 + std::uint32_t(rng() % (1u << 20));
      const auto any = [&] { return rng() % ((std::uint64_t(5) << f) / 4) * n + rng() % n; };
      add(any(), any(), any(), n);
    }
    add(123, 456, 789, 0);  // no samples: black
    // Sums past 64 bits (lamps): white, whatever the low words say; and just below 2^64.
    for (std::uint32_t n : {1u, 1000u, 1u << 20}) {
      add(exact_sum(1) << 64, exact_sum(3) << 90 | 12345, (exact_sum(1) << 64) - 1, n);
      add(exact_sum(0xffffffffu) << 64 | 7, exact_sum(t[200]) * n, exact_sum(1) << 80, n);
    }
    const std::vector<std::uint32_t> rgba = engine.encode_sums(sums, gamma);
    ASSERT_EQ(rgba.size(), sums.size());
    int mismatches = 0;
    for (std::size_t i = 0; i < sums.size(); ++i) {
      const gpu::pixel_sum& p = sums[i];
      const std::uint32_t want = encode_sum(gpu::red_sum(p), p.samples, t) |
                                 encode_sum(gpu::green_sum(p), p.samples, t) << 8 |
                                 encode_sum(gpu::blue_sum(p), p.samples, t) << 16 | 0xffu << 24;
      if (rgba[i] != want && ++mismatches <= 5)
        ADD_FAILURE() << "sums " << text(gpu::red_sum(p)) << ", " << text(gpu::green_sum(p)) << ", "
                      << text(gpu::blue_sum(p)) << " of " << p.samples << " samples: device "
                      << std::hex << rgba[i] << ", host " << want;
    }
    EXPECT_EQ(mismatches, 0);
  }
}

TEST_F(GpuSums, EncodingSpreadsOverRowsOfWorkgroupsWhenOneRowWouldPassTheLimit) {
  gpu::gpu_options o = test::gpu_test_options();
  o.caps.workgroup_count = 3;  // 1000 sums are 16 workgroups of 64: six rows of three
  gpu::gpu_context ctx(o);
  const scene s = test::small_scene("seed", 8, 1);
  gpu::gpu_engine engine(ctx, s);
  const byte_thresholds t = make_byte_thresholds(2, engine.sum_exponent());
  std::vector<gpu::pixel_sum> sums;
  for (std::uint32_t i = 0; i < 1000; ++i) {
    const std::uint64_t v = std::uint64_t(i) << 32;  // means from 0 to about 2^-10 * 1000
    sums.push_back({gpu::uvec2(0, std::uint32_t(v >> 32)), gpu::uvec2(0, 0),
                    gpu::uvec2(0, std::uint32_t(v >> 32)), 1, 0, 0, 0, 0, 0});
  }
  const std::vector<std::uint32_t> rgba = engine.encode_sums(sums, 2);
  ASSERT_EQ(rgba.size(), sums.size());
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const std::uint32_t byte = encode_sum(gpu::red_sum(sums[i]), 1, t);
    ASSERT_EQ(rgba[i], byte | byte << 16 | 0xffu << 24) << "sum " << i;
  }
  EXPECT_EQ(ctx.validation_messages(), 0u);
}

// A lamp-bright sky (10^6) around a sphere so dark (albedo 10^-12) that the samples hitting it
// are 10^-6: pixels on its silhouette mix the two, and 64 samples of 10^6 need more than 64
// bits at F = 42. Neither end may be clamped or rounded away (a 64-bit sum fitted to 10^6 keeps
// 22 fractional bits: 10^-6 would come out 4.6% short), the sums must not depend on batching or
// on how the sample range is split, and every pixel's mean is the CPU's (double) one.
TEST_F(GpuSums, SamplesOfAMillionAndAMillionthMixedAreSummedExactly) {
  scene s;
  s.name = "bright and dim";
  main_camera(s).pose.lookfrom = point3(0, 0, 3);
  main_camera(s).pose.lookat = point3(0, 0, 0);
  main_camera(s).pose.vfov = 60;
  s.render.width = 32;
  s.render.aspect = 1;
  s.render.spp = 64;
  s.render.jitter = true;
  s.render.max_depth = 4;
  s.sky = {color(1e6), color(1e6)};
  s.materials = {{"dark", {material_type::lambertian, color(1e-12), 0, 1.5}}};
  s.spheres = {sphere(point3(0, 0, 0), 1, 0)};
  const camera cam = test::scene_camera(s);
  const render_window win = whole_render(32, 32, 64);
  gpu::gpu_engine engine(gpu(), s);
  const gpu::sum_image whole = engine.render_sums({cam}, s.render, win)[0];
  EXPECT_EQ(whole.exponent, 42);

  // Split sample ranges and other batchings add up to the same bits.
  const gpu::sum_image first = engine.render_sums({cam}, s.render, {0, 0, 32, 32, 0, 23})[0];
  const gpu::sum_image rest = engine.render_sums({cam}, s.render, {0, 0, 32, 32, 23, 64})[0];
  const gpu::sum_image one_at_a_time =
      gpu::gpu_engine(gpu(), s, {.samples_per_dispatch = 1, .samples_per_submission = 3})
          .render_sums({cam}, s.render, win)[0];
  std::string why;
  EXPECT_TRUE(same_sums(one_at_a_time, whole, why)) << why;
  int past_64_bits = 0, all_dim = 0, mixed = 0, k_differs = 0;
  const framebuffer cpu = render_cpu(cam, s, s.render);
  for (std::size_t i = 0; i < whole.pixels.size(); ++i) {
    const gpu::pixel_sum& p = whole.pixels[i];
    ASSERT_TRUE(gpu::red_sum(first.pixels[i]) + gpu::red_sum(rest.pixels[i]) == gpu::red_sum(p))
        << "pixel " << i;
    past_64_bits += p.r_top != 0;
    const double mean = sum_mean(gpu::red_sum(p), p.samples, whole.exponent);
    const double want = cpu.at(int(i % 32), int(i / 32)).r;
    // Samples that missed the sphere: each brings 10^6, each hit 10^-6.
    const long k = std::lround(mean * 64 / 1e6), k_cpu = std::lround(want * 64 / 1e6);
    if (k != k_cpu) {
      ++k_differs;  // a grazing ray decided differently in float and in double
      continue;
    }
    all_dim += k == 0;
    mixed += k > 0 && k < 64;
    EXPECT_NEAR(mean, want, 1e-6 * want) << "pixel " << i << ", " << k << " of 64 missed";
  }
  EXPECT_GT(past_64_bits, 600);
  EXPECT_GT(all_dim, 200);
  EXPECT_GT(mixed, 40);
  EXPECT_LE(k_differs, 3);
}

TEST_F(GpuSums, AMillionSamplesOfTheSeedImageAreTheCpusWithinOneLevel) {
  // Every sample of a seed pixel is the same (no jitter), so a float running sum drifts: 192
  // instead of 193 at 262,144 samples, 4 to 5 levels at 2^20. Exact sums do not.
  scene s = builtin_scene("seed");
  s.render.width = 4;
  s.render.aspect = 2;
  s.render.spp = max_spp;
  const camera cam = test::scene_camera(s);
  const image_rgb8 gpu_img =
      gpu::gpu_engine(gpu(), s).render_encoded({cam}, s.render, whole_render(4, 2, max_spp))[0];
  const image_rgb8 cpu_img = test::cpu_image(s);
  const image_difference d = compare_images(gpu_img, cpu_img, 1);
  EXPECT_LE(d.max_abs, 1);
}

}  // namespace
}  // namespace rtvk
