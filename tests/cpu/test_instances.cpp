// Instances on the CPU: a group stored once and walked in its own space (two-level BVH, or the
// lesson's list with the book's instance wrapper) draws what copies of its objects draw, an
// ellipsoid is hit where its equation says, and exact ties keep the scan order.
#include <gtest/gtest.h>

#include <cmath>

#include "bvh_world.h"
#include "image_compare.h"
#include "object_group.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "world.h"

namespace rtvk {
namespace {

const char* const instances_json =
    R"({"materials":{"n":{"type":"normal"}},)"
    R"("camera":{"lookfrom":[0,1.5,4],"lookat":[0,0.3,0],"vfov":50},)"
    R"("render":{"gamma":1,"width":96,"aspect":"16:9","spp":1,"jitter":false},)"
    R"("quads":[{"Q":[-5,0,-5],"u":[0,0,10],"v":[10,0,0],"material":"n"}],)"
    R"("groups":{"thing":{"spheres":[{"center":[0,0.6,0],"radius":0.3,"material":"n"}],)"
    R"("boxes":[{"a":[-0.25,0,-0.25],"b":[0.25,0.3,0.25],"material":"n"}],)"
    R"("triangles":[{"vertices":[[0.3,0,0],[0.7,0,0],[0.5,0.6,0]],)"
    R"("normals":[[0,0,1],[0.5,0,1],[0,0.5,1]],"material":"n"}]}},)"
    R"("instances":[{"group":"thing"},)"
    R"({"group":"thing","transform":{"rotate":{"axis":[0,1,0],"degrees":40},"translate":[-1.2,0,-0.5]}},)"
    R"({"group":"thing","transform":{"scale":0.7,"translate":[1.1,0,0.3]}},)"
    R"({"group":"thing","transform":{"scale":[-1,1,1],"translate":[0.4,0,1]}}]})";

image_rgb8 image(const scene& s, bool use_bvh) {
  return quantize(render_cpu(test::scene_camera(s), s, s.render, {}, {.use_bvh = use_bvh}), 2);
}

// The same objects copied into place (flatten_instances) draw the same image: transforming the
// ray rather than the objects rounds differently, so a silhouette pixel may differ by a level
// or two (none did here), never a shape.
TEST(Instances, TheGroupsTreeDrawsWhatCopiesOfItsObjectsDraw) {
  const scene s = parse_scene_json(instances_json, "instances.json");
  ASSERT_EQ(s.groups.size(), 1u);
  ASSERT_EQ(s.instances.size(), 4u);
  ASSERT_TRUE(s.spheres.empty());  // stored once, in the group
  const scene copies = flatten_instances(s);
  ASSERT_EQ(copies.spheres.size(), 4u);
  const image_rgb8 want = image(copies, true);
  for (const bool use_bvh : {true, false}) {
    const image_difference d = compare_images(image(s, use_bvh), want, 2);
    EXPECT_LE(d.pixels_over, 96 * 54 / 500) << "use_bvh " << use_bvh;
    EXPECT_GE(d.psnr_db, 50) << "use_bvh " << use_bvh;
  }
  // The BVH and the list agree exactly (the same arithmetic in the same space).
  EXPECT_EQ(image(s, true).rgb, image(s, false).rgb);
}

// x^2/4 + y^2 + z^2 = 1 (a unit sphere stretched twice along x), moved to z = -5: rays along
// each axis meet it at x = 2 and y = 1, normals along the axes; at 45 degrees in x-y it is hit at
// (2 cos a, sin a) with tan a = 2 tan 45 / ... worked below, its normal along (x/4, y).
TEST(Instances, AnEllipsoidIsHitWhereItsEquationSays) {
  const scene s = parse_scene_json(
      R"({"materials":{"n":{"type":"normal"}},)"
      R"("groups":{"ball":{"spheres":[{"center":[0,0,0],"radius":1,"material":"n"}]}},)"
      R"("instances":[{"group":"ball","transform":{"scale":[2,1,1],"translate":[0,0,-5]}}]})",
      "ellipsoid.json");
  const bvh_world tree(s);
  const hittable_list list = make_world(s);
  for (const hittable* world :
       {static_cast<const hittable*>(&tree), static_cast<const hittable*>(&list)}) {
    hit_record rec;
    ASSERT_TRUE(world->hit(ray(point3(10, 0, -5), vec3(-1, 0, 0)), 1e-3, INFINITY, rec));
    EXPECT_NEAR(rec.t, 8, 1e-12);
    EXPECT_NEAR(rec.normal.x, 1, 1e-12);
    ASSERT_TRUE(world->hit(ray(point3(0, 5, -5), vec3(0, -2, 0)), 1e-3, INFINITY, rec));
    EXPECT_NEAR(rec.t, 2, 1e-12);  // the direction's length counts: 4 units at 2 a unit
    EXPECT_NEAR(rec.normal.y, 1, 1e-12);
    EXPECT_TRUE(rec.front_face);
    // Along (-1, -1, 0) from (4, 4, -5): x = y = 4 - t meets (4 - t)^2 / 4 + (4 - t)^2 = 1 at
    // 4 - t = 2 / sqrt(5); there the outward normal is along (x / 4, y) = (1, 4) / sqrt(17).
    ASSERT_TRUE(world->hit(ray(point3(4, 4, -5), vec3(-1, -1, 0)), 1e-3, INFINITY, rec));
    const double at = 2 / std::sqrt(5.0);
    EXPECT_NEAR(rec.t, 4 - at, 1e-12);
    EXPECT_NEAR(rec.p.x, at, 1e-12);
    EXPECT_NEAR(rec.normal.x, 1 / std::sqrt(17.0), 1e-12);
    EXPECT_NEAR(rec.normal.y, 4 / std::sqrt(17.0), 1e-12);
    // From inside: the normal faces the ray, and the hit is at the far side.
    ASSERT_TRUE(world->hit(ray(point3(0, 0, -5), vec3(1, 0, 0)), 1e-3, INFINITY, rec));
    EXPECT_NEAR(rec.t, 2, 1e-12);
    EXPECT_FALSE(rec.front_face);
    EXPECT_NEAR(rec.normal.x, -1, 1e-12);
  }
}

// Three quads at the very same place: the scene's own, then two instances of groups with other
// materials. A linear scan keeps the last it meets on an exact tie; so must the trees, whatever
// order they test them in.
TEST(Instances, ExactTiesGoToTheLaterInstanceAsInTheScan) {
  const scene s = parse_scene_json(
      R"({"materials":{"a":{"type":"normal"},"b":{"type":"normal"},"c":{"type":"normal"}},)"
      R"("quads":[{"Q":[-1,-1,-3],"u":[2,0,0],"v":[0,2,0],"material":"a"}],)"
      R"("groups":{"g":{"quads":[{"Q":[-1,-1,0],"u":[2,0,0],"v":[0,2,0],"material":"b"}]},)"
      R"("h":{"quads":[{"Q":[-1,-1,0],"u":[2,0,0],"v":[0,2,0],"material":"c"}]}},)"
      R"("instances":[{"group":"h","transform":{"translate":[0,0,-3]}},)"
      R"({"group":"g","transform":{"translate":[0,0,-3]}}]})",
      "ties.json");
  const bvh_world tree(s);
  const hittable_list list = make_world(s);
  for (const hittable* world :
       {static_cast<const hittable*>(&tree), static_cast<const hittable*>(&list)}) {
    hit_record rec;
    ASSERT_TRUE(world->hit(ray(point3(0.1, 0.2, 0), vec3(0, 0, -1)), 1e-3, INFINITY, rec));
    EXPECT_EQ(rec.material, 1u);  // g's "b", placed last
  }
}

// A group nothing places draws nothing, on the BVH as on the list: with no objects of the
// scene's own, its tree once sat at node 0 where the scene's should be, and the CPU's BVH drew it
// (found in review).
// A mirroring placement swaps a triangle's second and third corners (its front kept where its
// normals point): every per-corner value of its shading goes with its corner, the second
// texture coordinates and the vertex colors as the normals and uv (the colors were left behind).
TEST(Instances, AMirroredCopyKeepsEachCornersShading) {
  triangle_shading sh;
  for (std::size_t k = 0; k < 3; ++k) {
    sh.normal[k] = vec3(0, 0, 1 + double(k));
    sh.uv[k] = glm::dvec2(double(k), 0);
    sh.uv1[k] = glm::dvec2(0, double(k));
    sh.color[k] = glm::vec4(float(k), 0, 0, 1);
  }
  sh.has_uv = sh.has_uv1 = sh.has_color = true;
  const triangle_shading out =
      placed(sh, make_transform(vec3(-1, 1, 1), vec3(0, 1, 0), 0, vec3(0)));
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t from = k == 0 ? 0 : 3 - k;
    EXPECT_EQ(out.uv[k], sh.uv[from]) << k;
    EXPECT_EQ(out.uv1[k], sh.uv1[from]) << k;
    EXPECT_EQ(out.color[k], sh.color[from]) << k;
  }
}

TEST(Instances, AGroupNoInstancePlacesIsNotDrawn) {
  const scene s = parse_scene_json(
      R"({"materials":{"n":{"type":"normal"}},"spheres":[],)"
      R"("groups":{"ball":{"spheres":[{"center":[0,0,-3],"radius":1,"material":"n"}]}}})",
      "unplaced.json");
  const bvh_world tree(s);
  hit_record rec;
  EXPECT_FALSE(tree.hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 1e-3, INFINITY, rec));
  EXPECT_FALSE(make_world(s).hit(ray(point3(0, 0, 0), vec3(0, 0, -1)), 1e-3, INFINITY, rec));
}

}  // namespace
}  // namespace rtvk
