// Disks on the CPU: known answers worked by hand, their bounding boxes tight around the rim, the
// BVH finding exactly what the lesson's linear scan finds, and instances drawing what copies
// draw. tests/gpu/test_gpu_shapes.cpp holds the GPU's side.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "bvh_world.h"
#include "hittable_disk.h"
#include "image_compare.h"
#include "object_group.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "world.h"

namespace rtvk {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The unit disk at z = 0 facing +z: a ray straight down from (0.6, 0.0, 5) meets it at t = 5.
// Duff's basis for n = (0, 0, 1) is u = (1, 0, 0), v = (0, 1, 0), so the point's texture
// coordinates are (0.5 + 0.6 / 2, 0.5) = (0.8, 0.5).
TEST(Disk, HitsWhereWorkedByHand) {
  const disk d{point3(0, 0, 0), vec3(0, 0, 2), 1.0, 3};  // the normal's length does not matter
  const disk_geometry g = d.geometry();
  EXPECT_EQ(g.normal, vec3(0, 0, 1));
  EXPECT_EQ(g.u, vec3(1, 0, 0));
  EXPECT_EQ(g.v, vec3(0, 1, 0));
  EXPECT_EQ(g.D, 0);
  const ray down(point3(0.6, 0, 5), vec3(0, 0, -1));
  double t;
  ASSERT_TRUE(hit_disk(g, down, 0.001, inf, t));
  EXPECT_EQ(t, 5);
  hit_record rec{};
  record_disk_hit(g, 7, down, t, rec);
  EXPECT_EQ(rec.p, point3(0.6, 0, 0));
  EXPECT_EQ(rec.uv, real2(0.8, 0.5));
  EXPECT_TRUE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, 1));
  EXPECT_EQ(rec.material, 7u);
  // From below: the back face, the normal turned toward the ray.
  record_disk_hit(g, 7, ray(point3(0.6, 0, -5), vec3(0, 0, 1)), 5, rec);
  EXPECT_FALSE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, -1));
  // Inside the rim (0.999) a hit, outside (1.001) none; parallel to the plane none; past t_max
  // none; a NaN direction none.
  EXPECT_TRUE(hit_disk(g, ray(point3(0.999, 0, 1), vec3(0, 0, -1)), 0.001, inf, t));
  EXPECT_FALSE(hit_disk(g, ray(point3(1.001, 0, 1), vec3(0, 0, -1)), 0.001, inf, t));
  EXPECT_FALSE(hit_disk(g, ray(point3(0, 0, 1), vec3(1, 0, 0)), 0.001, inf, t));
  EXPECT_FALSE(hit_disk(g, down, 0.001, 4.9, t));
  EXPECT_FALSE(hit_disk(g, ray(point3(0, 0, 1), vec3(std::nan(""), 0, -1)), 0.001, inf, t));
  // The lesson's list finds the same through hittable_disk.
  hittable_disk h(d);
  ASSERT_TRUE(h.hit(down, 0.001, inf, rec));
  EXPECT_EQ(rec.t, 5);
  EXPECT_EQ(rec.material, 3u);
}

// The basis is orthonormal and right-handed for normals all over the sphere, including the
// -z pole where Duff's construction switches sign.
TEST(Disk, ItsAxesAreOrthonormalForEveryNormal) {
  std::mt19937 rng(11);
  std::normal_distribution<double> n01;
  std::vector<vec3> normals = {vec3(0, 0, -1), vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, -1, 0)};
  for (int i = 0; i < 1000; ++i) normals.push_back(vec3(n01(rng), n01(rng), n01(rng)));
  for (const vec3& n : normals) {
    const disk_geometry g = disk{point3(0), n, 1.0, 0}.geometry();
    EXPECT_NEAR(glm::dot(g.u, g.u), 1, 1e-12);
    EXPECT_NEAR(glm::dot(g.v, g.v), 1, 1e-12);
    EXPECT_NEAR(glm::dot(g.u, g.v), 0, 1e-12);
    EXPECT_NEAR(glm::dot(g.u, g.normal), 0, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(g.normal, g.u) - g.v), 0, 1e-12);
  }
}

// The box holds every rim point and touches the rim on each of its six faces: a box too small
// would let the BVH cull a disk the ray meets, one too large would only cost time.
TEST(Disk, ItsBoxIsTightAroundTheRim) {
  const disk d{point3(1, -2, 3), vec3(1, 2, -0.5), 0.7, 0};
  const auto [lo, hi] = d.bounds();
  const disk_geometry g = d.geometry();
  point3 seen_lo(inf), seen_hi(-inf);
  for (int i = 0; i < 20000; ++i) {
    const double a = 2 * std::numbers::pi * i / 20000;
    const point3 p = g.center + d.radius * (std::cos(a) * g.u + std::sin(a) * g.v);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(p[k], lo[k] - 1e-12);
      EXPECT_LE(p[k], hi[k] + 1e-12);
    }
    seen_lo = glm::min(seen_lo, p);
    seen_hi = glm::max(seen_hi, p);
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(seen_lo[k], lo[k], 1e-6) << "axis " << k;
    EXPECT_NEAR(seen_hi[k], hi[k], 1e-6) << "axis " << k;
  }
}

// Disks in every orientation among spheres and quads, some exactly over each other (the later
// wins the tie): the BVH draws the linear scan's image exactly, on one thread and on three.
scene disk_scene() {
  scene s = builtin_scene("materials");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 24; ++i)
    s.disks.push_back({point3(1.5 * u(rng), 0.5 * u(rng), -1.5 + 0.5 * u(rng)),
                       vec3(u(rng), u(rng), u(rng)), 0.1 + 0.2 * (u(rng) + 1), i % 5});
  s.disks.push_back(s.disks[3]);  // exactly over disk 3: the later one wins the tie
  s.disks.back().material = 0;
  s.quads.push_back({point3(1.2, -0.5, -2), vec3(1, 0, 0.3), vec3(0, 1.2, 0), 4});
  s.render.width = 96;
  s.render.spp = 3;
  return s;
}

TEST(Accel, BvhGivesTheLinearScansImageOverDisks) {
  const scene s = disk_scene();
  const camera cam = test::scene_camera(s);
  auto image = [&](engine_options e) { return quantize(render_cpu(cam, s, s.render, {}, e), 2); };
  const image_rgb8 reference = image({.use_bvh = false, .threads = 1});
  EXPECT_EQ(image({.use_bvh = true, .threads = 1}).rgb, reference.rgb);
  EXPECT_EQ(image({.use_bvh = true, .threads = 3}).rgb, reference.rgb);
  // And the disks are in the picture: without them it differs.
  scene none = s;
  none.disks.clear();
  EXPECT_NE(quantize(render_cpu(cam, none, none.render, {}, {.threads = 1}), 2).rgb, reference.rgb);
}

// A group of two disks placed three times, turned and scaled, draws what copies of the disks
// placed by hand draw; a non-uniform scale, which would make an ellipse, cannot be copied.
TEST(Instances, DisksInAGroupDrawWhatCopiesDraw) {
  scene s = builtin_scene("seed");
  object_group g;
  g.name = "coins";
  g.disks = {{point3(0, 0, 0), vec3(0, 1, 0.3), 0.3, 0},
             {point3(0.2, 0.1, 0), vec3(1, 0, 0), 0.2, 0}};
  s.groups.push_back(g);
  s.instances.push_back({0, make_transform(vec3(1), vec3(0, 1, 0), 0, vec3(-0.6, 0, -1))});
  s.instances.push_back({0, make_transform(vec3(0.7), vec3(0, 1, 0), 40, vec3(0.5, 0.1, -1.2))});
  s.instances.push_back({0, make_transform(vec3(-1, 1, 1), vec3(1, 0, 0), 25, vec3(0, 0.4, -1.5))});
  s.render.width = 96;
  const scene copies = flatten_instances(s);
  ASSERT_EQ(copies.disks.size(), 6u);
  const auto image = [](const scene& x, bool bvh) {
    return quantize(render_cpu(test::scene_camera(x), x, x.render, {}, {.use_bvh = bvh}), 2);
  };
  const image_rgb8 want = image(copies, true);
  for (const bool use_bvh : {true, false}) {
    const image_difference d = compare_images(image(s, use_bvh), want, 2);
    EXPECT_LE(d.pixels_over, 96 * 54 / 500) << "use_bvh " << use_bvh;
  }
  EXPECT_EQ(image(s, true).rgb, image(s, false).rgb);
  scene stretched = s;
  stretched.instances[0].placement = make_transform(vec3(2, 1, 1), vec3(0, 1, 0), 0, vec3(0));
  EXPECT_THROW(flatten_instances(stretched), std::invalid_argument);
}

// check_scene names the disk and the field.
TEST(Disk, ABadDiskIsRefusedByName) {
  scene s = builtin_scene("seed");
  s.disks.push_back({point3(0), vec3(0), 1.0, 0});
  EXPECT_THROW(
      {
        try {
          check_scene(s);
        } catch (const std::exception& e) {
          EXPECT_STREQ(e.what(), "seed: disk 0: normal is zero: the disk has no plane");
          throw;
        }
      },
      std::exception);
  s.disks[0] = {point3(0), vec3(0, 1, 0), -1.0, 0};
  EXPECT_THROW(check_scene(s), std::exception);
  s.disks[0] = {point3(0), vec3(0, 1, 0), 1.0, 99};
  EXPECT_THROW(check_scene(s), std::exception);
}

// A scene file's disks, the scene's own and a group's, read back from their dump unchanged; a
// transform places them; bad ones refused naming the field.
TEST(Disk, SceneFilesReadAndWriteThem) {
  const std::string text =
      R"({"materials":{"m":{"type":"lambertian","albedo":[0.5,0.5,0.5]}},"spheres":[],)"
      R"("disks":[{"center":[0,1,-2],"normal":[0,0,1],"radius":0.5,"material":"m"},)"
      R"({"center":[0,0,0],"normal":[0,1,0],"radius":1,"material":"m",)"
      R"("transform":{"scale":2,"translate":[1,0,0]}}],)"
      R"("groups":{"g":{"disks":[{"center":[0,0,0],"normal":[1,0,0],"radius":0.25,)"
      R"("material":"m"}]}},"instances":[{"group":"g"}]})";
  const scene s = parse_scene_json(text, "disks.json");
  ASSERT_EQ(s.disks.size(), 2u);
  EXPECT_EQ(s.disks[1].center, point3(1, 0, 0));
  EXPECT_EQ(s.disks[1].radius, 2);
  ASSERT_EQ(s.groups.size(), 1u);
  ASSERT_EQ(s.groups[0].disks.size(), 1u);
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("\"disks\""), std::string::npos);
  const scene again = parse_scene_json(dumped, "again.json");
  ASSERT_EQ(again.disks.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(again.disks[i].center, s.disks[i].center);
    EXPECT_EQ(again.disks[i].normal, s.disks[i].normal);
    EXPECT_EQ(again.disks[i].radius, s.disks[i].radius);
  }
  EXPECT_EQ(dump_scene_json(again), dumped);
  const auto refusal = [](const std::string& disk) {
    try {
      parse_scene_json(R"({"materials":{"m":{"type":"lambertian","albedo":[1,1,1]}},)"
                       R"("spheres":[],"disks":[)" + disk + "]}",
                       "bad.json");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(R"({"center":[0,0,0],"normal":[0,0,0],"radius":1,"material":"m"})"),
            "bad.json: /disks/0/normal: expected a nonzero normal");
  EXPECT_EQ(refusal(R"({"center":[0,0,0],"normal":[0,1,0],"radius":0,"material":"m"})"),
            "bad.json: /disks/0/radius: expected a radius > 0, got 0");
  EXPECT_NE(refusal(R"({"center":[0,0,0],"normal":[0,1,0],"radius":1,"material":"m",)"
                    R"("transform":{"scale":[1,2,1]}})")
                .find("/disks/0/transform: a disk can be scaled only uniformly"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"center":[0,0,0],"normal":[0,1,0],"radius":1,"material":"x"})"), "accepted");
}

}  // namespace
}  // namespace rtvk
