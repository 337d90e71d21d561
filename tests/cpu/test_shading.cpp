#include <gtest/gtest.h>

#include <memory>

#include "hittable_list.h"
#include "hittable_sphere.h"
#include "quantize.h"
#include "shading.h"

namespace rtvk {
namespace {

TEST(RayColor, StraightUpIsTheSkyBlue) {
  const hittable_list empty;
  // unit y = 1 -> t = 1 -> pure (0.5, 0.7, 1.0).
  const color c = ray_color(ray(point3(0, 0, 0), vec3(0, 3, 0)), empty);
  EXPECT_DOUBLE_EQ(c.r, 0.5);
  EXPECT_DOUBLE_EQ(c.g, 0.7);
  EXPECT_DOUBLE_EQ(c.b, 1.0);
}

TEST(RayColor, HorizonAndStraightDown) {
  const hittable_list empty;
  const color horizon = ray_color(ray(point3(0, 0, 0), vec3(1, 0, 0)), empty);  // t = 0.5
  EXPECT_DOUBLE_EQ(horizon.r, 0.75);
  EXPECT_DOUBLE_EQ(horizon.g, 0.85);
  EXPECT_DOUBLE_EQ(horizon.b, 1.0);
  const color down = ray_color(ray(point3(0, 0, 0), vec3(0, -1, 0)), empty);  // t = 0
  EXPECT_DOUBLE_EQ(down.r, 1.0);
  EXPECT_DOUBLE_EQ(down.g, 1.0);
}

TEST(RayColor, HitIsColoredByItsNormal) {
  hittable_list world;
  world.add(std::make_shared<hittable_sphere>(point3(0, 0, -1), 0.5));
  // Looking down -z the hit is at (0, 0, -0.5), normal (0, 0, 1) -> color (0.5, 0.5, 1).
  const color c = ray_color(ray(point3(0, 0, 0), vec3(0, 0, -1)), world);
  EXPECT_DOUBLE_EQ(c.r, 0.5);
  EXPECT_DOUBLE_EQ(c.g, 0.5);
  EXPECT_DOUBLE_EQ(c.b, 1.0);
  // From above, looking down: normal (0, 1, 0) -> (0.5, 1, 0.5).
  const color top = ray_color(ray(point3(0, 2, -1), vec3(0, -1, 0)), world);
  EXPECT_DOUBLE_EQ(top.r, 0.5);
  EXPECT_DOUBLE_EQ(top.g, 1.0);
  EXPECT_DOUBLE_EQ(top.b, 0.5);
}

TEST(Quantize, LessonRuleWithClamping) {
  EXPECT_EQ(to_byte(0.0), 0);
  EXPECT_EQ(to_byte(1.0), 255);
  EXPECT_EQ(to_byte(0.5), 127);  // int(127.9995)
  EXPECT_EQ(to_byte(1.0 / 255.999), 1);
  EXPECT_EQ(to_byte(-0.25), 0);
  EXPECT_EQ(to_byte(7.0), 255);
  EXPECT_EQ(to_byte(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(to_byte(std::numeric_limits<double>::infinity()), 255);
}

}  // namespace
}  // namespace rtvk
