#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hittable_list.h"
#include "sphere.h"

namespace rtvk {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(Sphere, Miss) {
  const sphere s(point3(0, 0, -1), 0.5);
  hit_record rec;
  EXPECT_FALSE(s.hit(ray(point3(0, 0, 0), vec3(0, 1, 0)), 0, inf, rec));
  EXPECT_FALSE(s.hit(ray(point3(0, 0, 0), vec3(1, 0, -1)), 0, inf, rec));
}

TEST(Sphere, HitFromOutsideTakesNearestRoot) {
  const sphere s(point3(0, 0, -3), 1);
  hit_record rec;
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(0, 0, -2)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 1.0);  // direction of length 2: the near surface at z = -2
  EXPECT_DOUBLE_EQ(rec.p.z, -2.0);
  EXPECT_TRUE(rec.front_face);
  EXPECT_DOUBLE_EQ(rec.normal.z, 1.0);
}

TEST(Sphere, HitFromInsideNormalFacesTheRay) {
  const sphere s(point3(0, 0, 0), 2);
  hit_record rec;
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(1, 0, 0)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 2.0);
  EXPECT_FALSE(rec.front_face);
  EXPECT_DOUBLE_EQ(rec.normal.x, -1.0);  // outward is +x; stored normal opposes the ray
  EXPECT_LT(glm::dot(rec.normal, vec3(1, 0, 0)), 0);
}

TEST(Sphere, RootsOutsideTheInterval) {
  const sphere s(point3(0, 0, -3), 1);  // roots at t = 2 and t = 4
  const ray r(point3(0, 0, 0), vec3(0, 0, -1));
  hit_record rec;
  EXPECT_FALSE(s.hit(r, 0, 1.5, rec));    // both beyond t_max
  EXPECT_FALSE(s.hit(r, 4.5, inf, rec));  // both before t_min
  ASSERT_TRUE(s.hit(r, 2.5, inf, rec));   // near root excluded: the far one
  EXPECT_DOUBLE_EQ(rec.t, 4.0);
  EXPECT_FALSE(rec.front_face);
  ASSERT_TRUE(s.hit(r, 2.0, 2.0, rec));  // the interval is closed
  EXPECT_DOUBLE_EQ(rec.t, 2.0);
}

TEST(Sphere, TangentRayHitsOnce) {
  const sphere s(point3(0, 1, -3), 1);  // the ray along -z at y = 0 grazes its bottom
  hit_record rec;
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 3.0);
  EXPECT_DOUBLE_EQ(rec.p.y, 0.0);
  // The normal is perpendicular to a grazing ray; dot == 0 is not "< 0", so it counts as a back
  // face and the stored normal is the flipped outward one, as in the lesson.
  EXPECT_DOUBLE_EQ(std::abs(rec.normal.y), 1.0);
  EXPECT_DOUBLE_EQ(glm::dot(rec.normal, vec3(0, 0, -1)), 0.0);
  EXPECT_FALSE(s.hit(ray(point3(0, -1e-9, 0), vec3(0, 0, -1)), 0, inf, rec));  // just below: miss
}

TEST(HittableList, ClosestOfOverlappingHits) {
  hittable_list world;
  world.add(std::make_shared<sphere>(point3(0, 0, -10), 1));  // added first, but farther
  world.add(std::make_shared<sphere>(point3(0, 0, -5), 1));
  world.add(std::make_shared<sphere>(point3(0, 0, -7), 3));  // overlaps, near side at t = 4
  hit_record rec;
  ASSERT_TRUE(world.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 4.0);
  EXPECT_DOUBLE_EQ(rec.p.z, -4.0);
}

TEST(HittableList, EmptyListMisses) {
  const hittable_list world;
  hit_record rec;
  EXPECT_FALSE(world.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
}

}  // namespace
}  // namespace rtvk
