#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <tuple>

#include "camera.h"
#include "image_io.h"
#include "lesson_reference.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

image_rgb8 render_seed(double aspect, int width) {
  return test::seed_image(aspect, width);
}

// Nearest hit of the ray from the origin along d with a sphere, by the full quadratic
// (not rtvk's half-b form): t^2 |d|^2 - 2t d.c + |c|^2 - r^2 = 0.
double nearest_t(glm::dvec3 d, glm::dvec3 c, double r) {
  const double a = glm::dot(d, d), b = -2 * glm::dot(d, c), cc = glm::dot(c, c) - r * r;
  const double disc = b * b - 4 * a * cc;
  return disc < 0 ? -1 : (-b - std::sqrt(disc)) / (2 * a);
}

void expect_pixel(const image_rgb8& img, int x, int y, glm::dvec3 c) {
  const std::uint8_t* p = img.pixel(x, y);
  EXPECT_EQ(int(p[0]), int(255.999 * c.r)) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[1]), int(255.999 * c.g)) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[2]), int(255.999 * c.b)) << "pixel " << x << "," << y;
}

// The direction through pixel (x, y) of a 400x225 image, from the lesson's viewport by hand.
glm::dvec3 direction(int x, int y) {
  const double vw = 2.0 * 16.0 / 9.0, vh = 2.0;
  const double u = x / 399.0, v = (224 - y) / 224.0;
  return {vw * (u - 0.5), vh * (v - 0.5), -1.0};
}

TEST(SeedImage, KnownAnswerPixels) {
  const image_rgb8 img = render_seed(16.0 / 9.0, 400);
  ASSERT_EQ(img.width, 400);
  ASSERT_EQ(img.height, 225);

  // Center: the small sphere, nearly head on.
  const glm::dvec3 dc = direction(200, 112), ball(0, 0, -1);
  const double tc = nearest_t(dc, ball, 0.5);
  ASSERT_GT(tc, 0);
  expect_pixel(img, 200, 112, 0.5 * ((tc * dc - ball) / 0.5 + 1.0));

  // Top-left corner: sky, t = 0.5 (unit y + 1).
  const glm::dvec3 dk = direction(0, 0);
  const double ty = 0.5 * (dk.y / std::sqrt(glm::dot(dk, dk)) + 1.0);
  expect_pixel(img, 0, 0, (1 - ty) * glm::dvec3(1) + ty * glm::dvec3(0.5, 0.7, 1.0));

  // Bottom center: the ground sphere, passing below the small one.
  const glm::dvec3 dg = direction(200, 224), ground(0, -100.5, -1);
  ASSERT_LT(nearest_t(dg, ball, 0.5), 0);
  const double tg = nearest_t(dg, ground, 100);
  ASSERT_GT(tg, 0);
  expect_pixel(img, 200, 224, 0.5 * ((tg * dg - ground) / 100.0 + 1.0));
}

TEST(SeedImage, IsTheLessonsImageByteForByte) {
  for (auto [aspect, width] : {std::tuple{16.0 / 9.0, 400},
                               {16.0 / 9.0, 1},
                               {16.0 / 9.0, 2},
                               {1.0, 7},
                               {2.0, 333},
                               {1.5, 101},
                               {0.5, 64},
                               {1000.0, 10}}) {
    EXPECT_EQ(encode_ppm(render_seed(aspect, width), ppm_encoding::ascii_p3),
              lesson::render_seed_p3(aspect, width))
        << "aspect " << aspect << " width " << width;
  }
}

TEST(SeedImage, OnePixelImageHasNoNaN) {
  const scene seed = builtin_scene("seed");
  const framebuffer fb = render_cpu(camera(1.0, 1), seed, seed.render);
  ASSERT_EQ(fb.width(), 1);
  ASSERT_EQ(fb.height(), 1);
  const color c = fb.at(0, 0);
  EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
  EXPECT_DOUBLE_EQ(c.b, 1.0);  // the center ray hits the ball head on: normal (0, 0, 1)
}

TEST(SeedImage, RoundTripsThroughEveryFormat) {
  const image_rgb8 img = render_seed(16.0 / 9.0, 160);
  test::temp_dir dir;
  for (const char* name : {"a.png", "b.ppm"}) {
    write_image(img, dir.path() / name);
    const image_rgb8 back = read_image(dir.path() / name);
    EXPECT_EQ(back.width, img.width) << name;
    EXPECT_EQ(back.height, img.height) << name;
    EXPECT_EQ(back.rgb, img.rgb) << name;
  }
  write_image(img, dir.path() / "c.ppm", ppm_encoding::binary_p6);
  EXPECT_EQ(read_image(dir.path() / "c.ppm").rgb, img.rgb);
}

}  // namespace
}  // namespace rtvk
