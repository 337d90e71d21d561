#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bvh_world.h"
#include "gpu_fixture.h"
#include "hittable_list.h"
#include "hittable_sphere.h"
#include "probe.h"

namespace rtvk {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(Sphere, Miss) {
  const hittable_sphere s(point3(0, 0, -1), 0.5);
  hit_record rec{};
  EXPECT_FALSE(s.hit(ray(point3(0, 0, 0), vec3(0, 1, 0)), 0, inf, rec));
  EXPECT_FALSE(s.hit(ray(point3(0, 0, 0), vec3(1, 0, -1)), 0, inf, rec));
}

TEST(Sphere, HitFromOutsideTakesNearestRoot) {
  const hittable_sphere s(point3(0, 0, -3), 1);
  hit_record rec{};
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(0, 0, -2)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 1.0);  // direction of length 2: the near surface at z = -2
  EXPECT_DOUBLE_EQ(rec.p.z, -2.0);
  EXPECT_TRUE(rec.front_face);
  EXPECT_DOUBLE_EQ(rec.normal.z, 1.0);
}

TEST(Sphere, HitFromInsideNormalFacesTheRay) {
  const hittable_sphere s(point3(0, 0, 0), 2);
  hit_record rec{};
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(1, 0, 0)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 2.0);
  EXPECT_FALSE(rec.front_face);
  EXPECT_DOUBLE_EQ(rec.normal.x, -1.0);  // outward is +x; stored normal opposes the ray
  EXPECT_LT(glm::dot(rec.normal, vec3(1, 0, 0)), 0);
}

TEST(Sphere, RootsOutsideTheInterval) {
  const hittable_sphere s(point3(0, 0, -3), 1);  // roots at t = 2 and t = 4
  const ray r(point3(0, 0, 0), vec3(0, 0, -1));
  hit_record rec{};
  EXPECT_FALSE(s.hit(r, 0, 1.5, rec));    // both beyond t_max
  EXPECT_FALSE(s.hit(r, 4.5, inf, rec));  // both before t_min
  ASSERT_TRUE(s.hit(r, 2.5, inf, rec));   // near root excluded: the far one
  EXPECT_DOUBLE_EQ(rec.t, 4.0);
  EXPECT_FALSE(rec.front_face);
  ASSERT_TRUE(s.hit(r, 2.0, 2.0, rec));  // the interval is closed
  EXPECT_DOUBLE_EQ(rec.t, 2.0);
}

TEST(Sphere, TangentRayHitsOnce) {
  const hittable_sphere s(point3(0, 1, -3), 1);  // the ray along -z at y = 0 grazes its bottom
  hit_record rec{};
  ASSERT_TRUE(s.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 3.0);
  EXPECT_DOUBLE_EQ(rec.p.y, 0.0);
  // The normal is perpendicular to a grazing ray; dot == 0 is not "< 0", so it counts as a back
  // face and the stored normal is the flipped outward one, as in the lesson.
  EXPECT_DOUBLE_EQ(std::abs(rec.normal.y), 1.0);
  EXPECT_DOUBLE_EQ(glm::dot(rec.normal, vec3(0, 0, -1)), 0.0);
  EXPECT_FALSE(s.hit(ray(point3(0, -1e-9, 0), vec3(0, 0, -1)), 0, inf, rec));  // just below: miss
}

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Rays no camera should make, but that float overflow or a zero-length scatter direction can:
// every one of them gives NaN roots, which must not count as hits (one would poison a pixel).
struct degenerate_case {
  const char* what;
  point3 origin;
  vec3 direction;
};
const degenerate_case degenerate_rays[] = {
    {"zero direction, outside", point3(0, 0, 0), vec3(0, 0, 0)},
    {"zero direction, inside", point3(0, 0, -3), vec3(0, 0, 0)},
    {"NaN direction", point3(0, 0, 0), vec3(nan, 0, -1)},
    {"infinite direction", point3(0, 0, 0), vec3(0, 0, -inf)},
    {"NaN origin", point3(nan, 0, 0), vec3(0, 0, -1)},
};

TEST(Sphere, AnOverflowingRootIsNoHit) {
  // radius^2 overflows to infinity: the roots are -inf and +inf, and +inf <= t_max = inf.
  const hittable_sphere huge(point3(0, 0, -3), 1e155);
  double t = -1;
  EXPECT_FALSE(hit_distance(huge.data(), ray(point3(0, 0, 0), vec3(0, 0, -1)), 0.001, inf, t)) << t;
}

TEST(Sphere, DegenerateRaysAreNoHit) {
  const hittable_sphere s(point3(0, 0, -3), 1);
  for (const degenerate_case& c : degenerate_rays) {
    hit_record rec{};
    double t = -1;
    EXPECT_FALSE(hit_distance(s.data(), ray(c.origin, c.direction), 0.001, inf, t))
        << c.what << " t=" << t;
    EXPECT_FALSE(s.hit(ray(c.origin, c.direction), 0.001, inf, rec)) << c.what;
    // The BVH over the same sphere agrees: no NaN slips through its traversal either.
    EXPECT_FALSE(bvh_world({s.data()}).hit(ray(c.origin, c.direction), 0.001, inf, rec)) << c.what;
  }
}

class GpuSphere : public test::GpuTest {};

TEST_F(GpuSphere, DegenerateRaysAreNoHitOnTheGpuEither) {
  std::vector<gpu::hit_probe_entry> entries;
  auto add = [&](const point3& o, const vec3& d) {
    gpu::hit_probe_entry e{};
    e.origin = glm::vec3(o);
    e.direction = glm::vec3(d);
    e.t_min = 0.001f;
    e.t_max = 3.402823466e+38f;
    e.center = glm::vec3(0, 0, -3);
    e.radius = 1;
    entries.push_back(e);
  };
  add(point3(0, 0, 0), vec3(0, 0, -1));  // a plain hit at t = 2: the probe itself works
  for (const degenerate_case& c : degenerate_rays) add(c.origin, c.direction);
  const std::vector<gpu::hit_probe_entry> out = gpu::run_hit_probe(gpu(), entries);
  EXPECT_EQ(out[0].hit, 1u);
  EXPECT_EQ(out[0].t, 2.0f);
  for (std::size_t k = 1; k < out.size(); ++k)
    EXPECT_EQ(out[k].hit, 0u) << degenerate_rays[k - 1].what << " t=" << out[k].t;
}

TEST(HittableList, ClosestOfOverlappingHits) {
  hittable_list world;
  world.add(std::make_shared<hittable_sphere>(point3(0, 0, -10), 1));  // added first, but farther
  world.add(std::make_shared<hittable_sphere>(point3(0, 0, -5), 1));
  world.add(
      std::make_shared<hittable_sphere>(point3(0, 0, -7), 3));  // overlaps, near side at t = 4
  hit_record rec{};
  ASSERT_TRUE(world.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
  EXPECT_DOUBLE_EQ(rec.t, 4.0);
  EXPECT_DOUBLE_EQ(rec.p.z, -4.0);
}

TEST(HittableList, EmptyListMisses) {
  const hittable_list world;
  hit_record rec{};
  EXPECT_FALSE(world.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 0, inf, rec));
}

}  // namespace
}  // namespace rtvk
