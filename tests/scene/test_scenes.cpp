// Built-in scenes are valid at every size, and check_scene refuses what no renderer can draw.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "errors.h"
#include "scene.h"

namespace rtvk {
namespace {

TEST(SpheresScene, TheLargestStillRestsEverySphereOnTheGround) {
  // At 4,000,000 the scattering square (2000 units a side) is wider than the radius-1000 ground:
  // its corners once gave sqrt of a negative number, NaN centers, and a scene file with nulls.
  const scene s = builtin_scene("spheres:4000000");
  ASSERT_EQ(s.spheres.size(), 4000001u);
  std::size_t off_ground = 0;
  for (std::size_t i = 1; i < s.spheres.size(); ++i)
    off_ground +=
        !(std::abs(glm::length(s.spheres[i].center - point3(0, -1000, 0)) - 1000.2) < 1e-6);
  EXPECT_EQ(off_ground, 0u);
  EXPECT_NO_THROW(check_scene(s));
}

TEST(CheckScene, RefusesCentersAndRadiiThatAreNotFiniteOrTooLargeForTheGpu) {
  scene s = builtin_scene("seed");
  s.spheres[0].center.y = std::numeric_limits<double>::quiet_NaN();
  try {
    check_scene(s);
    ADD_FAILURE() << "accepted";
  } catch (const usage_error& e) {
    EXPECT_STREQ(e.what(), "seed: sphere 0: center must be finite and within +-1e18, got 0,nan,-1");
  }
  s.spheres[0].center.y = std::numeric_limits<double>::infinity();
  EXPECT_THROW(check_scene(s), usage_error);
  s.spheres[0].center.y = 2e18;  // finite in double, but its square overflows the GPU's float
  EXPECT_THROW(check_scene(s), usage_error);
  s.spheres[0].center.y = 1e18;
  EXPECT_NO_THROW(check_scene(s));
  s.spheres[0].radius = 1e155;
  EXPECT_THROW(check_scene(s), usage_error);
}

}  // namespace
}  // namespace rtvk
