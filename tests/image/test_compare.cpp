#include <gtest/gtest.h>

#include "camera.h"
#include "image_compare.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene.h"

namespace rtvk {
namespace {

image_rgb8 seed(int width) {
  return test::seed_image(16.0 / 9.0, width);
}

image_rgb8 upside_down(const image_rgb8& img) {
  image_rgb8 out = img;
  for (int y = 0; y < img.height; ++y)
    std::copy_n(img.pixel(0, img.height - 1 - y), img.width * 3,
                out.rgb.begin() + std::ptrdiff_t(y) * img.width * 3);
  return out;
}

image_rgb8 shifted_right(const image_rgb8& img) {
  image_rgb8 out = img;
  for (int y = 0; y < img.height; ++y)
    for (int x = img.width - 1; x > 0; --x)
      std::copy_n(img.pixel(x - 1, y), 3,
                  out.rgb.begin() + (std::ptrdiff_t(y) * img.width + x) * 3);
  return out;
}

TEST(Compare, IdenticalImages) {
  const image_rgb8 a = seed(120);
  const image_difference d = compare_images(a, a, 0);
  EXPECT_EQ(d.max_abs, 0);
  EXPECT_EQ(d.pixels_over, 0);
  EXPECT_TRUE(std::isinf(d.psnr_db));
  EXPECT_TRUE(agrees(d, agreement{}));
}

TEST(Compare, KnownDifference) {
  image_rgb8 a{2, 1, {10, 10, 10, 10, 10, 10}};
  image_rgb8 b{2, 1, {10, 10, 10, 10, 15, 10}};  // one channel of one pixel off by 5
  const image_difference d = compare_images(a, b, 1);
  EXPECT_EQ(d.max_abs, 5);
  EXPECT_DOUBLE_EQ(d.mean_abs, 5.0 / 6);
  EXPECT_EQ(d.pixels_over, 1);
  EXPECT_DOUBLE_EQ(d.share_over, 0.5);
  EXPECT_NEAR(d.psnr_db, 10 * std::log10(255.0 * 255 / (25.0 / 6)), 1e-9);
  EXPECT_EQ(compare_images(a, b, 5).pixels_over, 0);
}

TEST(Compare, UpsideDownAndShiftedImagesAreDifferent) {
  const image_rgb8 a = seed(200);
  for (const image_rgb8& wrong : {upside_down(a), shifted_right(a)}) {
    const image_difference d = compare_images(a, wrong, agreement{}.tolerance);
    EXPECT_FALSE(agrees(d, agreement{}));
    EXPECT_GT(d.share_over, 0.01);
  }
}

TEST(Compare, HeatmapIsBlackWhereEqual) {
  const image_rgb8 a = seed(64);
  const image_rgb8 h = difference_heatmap(a, a);
  EXPECT_EQ(h.rgb, std::vector<std::uint8_t>(a.rgb.size(), 0));
}

TEST(Compare, HeatmapRunsThroughRedAndYellowToWhiteByTheWorstChannel) {
  // Worst-channel differences 0, 16, 32, 64 and 200 levels; t = min(1, d / 64) is 0, 0.25,
  // 0.5, 1, 1, and the color is 255 * clamp(3t, 3t - 1, 3t - 2 to [0, 1]):
  //   t = 0.25: (255 * 0.75, 0, 0) = (191, 0, 0), dark red
  //   t = 0.5:  (255, 255 * 0.5, 0) = (255, 127, 0), orange
  //   t = 1:    (255, 255, 255), white, and no brighter for 200 levels
  const image_rgb8 a{5, 1, {10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 250, 250, 250}};
  const image_rgb8 b{5, 1, {10, 10, 10, 10, 26, 12, 10, 42, 10, 74, 10, 10, 250, 50, 250}};
  EXPECT_EQ(
      difference_heatmap(a, b).rgb,
      (std::vector<std::uint8_t>{0, 0, 0, 191, 0, 0, 255, 127, 0, 255, 255, 255, 255, 255, 255}));
}

}  // namespace
}  // namespace rtvk
