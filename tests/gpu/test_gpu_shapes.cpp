// Quads, boxes and triangles on the GPU: the book's quads scene and a mixed scene as the CPU draws
// them, the BVH as the linear scan, and closed meshes watertight in float too.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "gpu_fixture.h"
#include "image_compare.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
#include "probe.h"
#include "render_gpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "world.h"

namespace rtvk {
namespace {

class GpuShapes : public test::GpuTest {};

image_difference gpu_vs_cpu(gpu::gpu_context& ctx, const scene& s) {
  return compare_images(test::gpu_image(ctx, s), test::cpu_image(s),
                        monte_carlo_agreement.tolerance);
}

// Measured on lavapipe (Mesa 22.3): 88.0 dB, 1 pixel over 2 levels of 40,000.
TEST_F(GpuShapes, TheBooksQuadsSceneMatchesTheCpu) {
  const scene s = test::small_scene("quads", 200, 16);
  const image_difference d = gpu_vs_cpu(gpu(), s);
  const agreement rule = test::measured_agreement(88.0, 2.5e-5, 200 * 200);
  EXPECT_GE(d.psnr_db, rule.min_psnr_db);
  EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels over 2 levels";
}

// A scene of every kind under the lesson's normal shading, no random numbers: the images agree
// but for pixels on silhouettes, where float and double may round a ray either way (on lavapipe,
// Mesa 22.3 and 25, not one pixel differs by more than 2 levels; the bound leaves room for
// another device's rounding).
TEST_F(GpuShapes, EveryKindOfObjectUnderNormalShadingMatchesTheCpu) {
  scene s = builtin_scene("seed");
  add_box(s, point3(-1.6, -0.5, -2.2), point3(-0.9, 0.2, -1.5), 0,
          make_transform(vec3(1), vec3(0, 1, 0), 30, vec3(0)));
  s.quads.push_back({point3(0.7, -0.5, -1.8), vec3(0.8, 0, 0.3), vec3(0, 0.9, 0), 0});
  const test::indexed_mesh m = test::cube_sphere(5, 0.3);
  for (const auto& f : m.faces)
    s.triangles.push_back(
        {{m.positions[f[0]] + vec3(0.45, 0.35, -1.2), m.positions[f[1]] + vec3(0.45, 0.35, -1.2),
          m.positions[f[2]] + vec3(0.45, 0.35, -1.2)},
         0});
  s.render.width = 160;
  const image_difference d = gpu_vs_cpu(gpu(), s);
  EXPECT_LE(d.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  EXPECT_GE(d.psnr_db, 50);
}

// Instances from a scene file: one group (a sphere, a box, a smooth triangle) placed four times,
// turned, scaled, mirrored; and one without spheres stretched non-uniformly. Under normal
// shading, the GPU draws the placed objects as the CPU does (the same bounds as above).
TEST_F(GpuShapes, InstancesOfGroupsMatchTheCpu) {
  const scene s = parse_scene_json(
      R"({"materials":{"n":{"type":"normal"}},)"
      R"("camera":{"lookfrom":[0,1.5,4],"lookat":[0,0.3,0],"vfov":50},)"
      R"("render":{"gamma":1,"width":160,"aspect":"16:9","spp":1,"jitter":false},)"
      R"("quads":[{"Q":[-5,0,-5],"u":[0,0,10],"v":[10,0,0],"material":"n"}],)"
      R"("groups":{"thing":{"spheres":[{"center":[0,0.6,0],"radius":0.3,"material":"n"}],)"
      R"("boxes":[{"a":[-0.25,0,-0.25],"b":[0.25,0.3,0.25],"material":"n"}],)"
      R"("triangles":[{"vertices":[[0.3,0,0],[0.7,0,0],[0.5,0.6,0]],)"
      R"("normals":[[0,0,1],[0.5,0,1],[0,0.5,1]],"material":"n"}]},)"
      R"("wedge":{"triangles":[{"vertices":[[0,0,0],[0.4,0,0],[0,0.4,0.2]],"material":"n"}]}},)"
      R"("instances":[{"group":"thing"},)"
      R"({"group":"thing","transform":{"rotate":{"axis":[0,1,0],"degrees":40},"translate":[-1.2,0,-0.5]}},)"
      R"({"group":"thing","transform":{"scale":0.7,"translate":[1.1,0,0.3]}},)"
      R"({"group":"thing","transform":{"scale":[-1,1,1],"translate":[0.4,0,1]}},)"
      R"({"group":"wedge","transform":{"scale":[3,1,0.5],"rotate":{"axis":[1,1,0],"degrees":25},"translate":[-0.6,0.8,0.8]}}]})",
      "instances.json");
  ASSERT_EQ(s.groups.size(), 2u);  // stored once: the GPU walks each group's tree in its space
  ASSERT_EQ(s.instances.size(), 5u);
  const image_difference d = gpu_vs_cpu(gpu(), s);
  EXPECT_LE(d.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  EXPECT_GE(d.psnr_db, 50);
  // What copies of the objects draw (flatten_instances: the objects placed one by one).
  const image_difference copies =
      compare_images(test::gpu_image(gpu(), s), test::cpu_image(flatten_instances(s)), 2);
  EXPECT_LE(copies.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  // The GPU's scan without the BVH draws what its two-level walk draws.
  auto image = [&](bool bvh) {
    return quantize(gpu::render_gpu(gpu(), test::scene_camera(s), s, s.render, {},
                                    {.engine = {.use_bvh = bvh}}),
                    2);
  };
  EXPECT_EQ(image(true).rgb, image(false).rgb);
}

// An ellipsoid (a unit sphere stretched 3 times along x and turned 30 degrees about z), and a
// mirrored, stretched box, under normal shading: the GPU carries hits back from each group's
// space as the CPU does.
TEST_F(GpuShapes, EllipsoidsAndStretchedInstancesMatchTheCpu) {
  const scene s = parse_scene_json(
      R"({"materials":{"n":{"type":"normal"}},)"
      R"("camera":{"lookfrom":[0,1,5],"lookat":[0,0.5,0],"vfov":45},)"
      R"("render":{"gamma":1,"width":160,"aspect":"16:9","spp":1,"jitter":false},)"
      R"("groups":{"ball":{"spheres":[{"center":[0,0,0],"radius":0.5,"material":"n"}]},)"
      R"("crate":{"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"n"}]}},)"
      R"("instances":[{"group":"ball","transform":{"scale":[3,1,1],"rotate":{"axis":[0,0,1],"degrees":30},"translate":[-0.5,1,0]}},)"
      R"({"group":"ball","transform":{"scale":[0.5,2,0.5],"translate":[1.6,0.2,0.5]}},)"
      R"({"group":"crate","transform":{"scale":[-1.5,0.4,0.8],"rotate":{"axis":[0,1,0],"degrees":20},"translate":[0.5,-0.6,-0.5]}}]})",
      "ellipsoids.json");
  const image_difference d = gpu_vs_cpu(gpu(), s);
  EXPECT_LE(d.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  EXPECT_GE(d.psnr_db, 50);
}

// Through the world probe, ray by ray: exact ties between the scene's quad and two instances'
// quads at the same place go to the last instance, as in the CPU's scan, through the two-level
// walk and the scan alike; and an ellipsoid is hit where its equation says (x^2/4 + y^2 + z^2 =
// 1 at z = -5; bvh_world's test, in float).
TEST_F(GpuShapes, InstancesKeepTheScansTiesAndHitEllipsoidsWhereTheCpuDoes) {
  const scene s = parse_scene_json(
      R"({"materials":{"a":{"type":"normal"},"b":{"type":"normal"},"c":{"type":"normal"}},)"
      R"("quads":[{"Q":[-1,-1,-3],"u":[2,0,0],"v":[0,2,0],"material":"a"}],)"
      R"("groups":{"g":{"quads":[{"Q":[-1,-1,0],"u":[2,0,0],"v":[0,2,0],"material":"b"}]},)"
      R"("h":{"quads":[{"Q":[-1,-1,0],"u":[2,0,0],"v":[0,2,0],"material":"c"}]},)"
      R"("ball":{"spheres":[{"center":[0,0,0],"radius":1,"material":"c"}]}},)"
      R"("instances":[{"group":"h","transform":{"translate":[0,0,-3]}},)"
      R"({"group":"g","transform":{"translate":[0,0,-3]}},)"
      R"({"group":"ball","transform":{"scale":[2,1,1],"translate":[10,0,-5]}}]})",
      "ties.json");
  std::vector<gpu::world_probe_entry> entries(3);
  entries[0].origin = glm::vec3(0.1f, 0.2f, 0);
  entries[0].direction = glm::vec3(0, 0, -1);
  entries[1].origin = glm::vec3(20, 0, -5);  // along -x into the ellipsoid at x = 12
  entries[1].direction = glm::vec3(-1, 0, 0);
  entries[2].origin = glm::vec3(14, 4, -5);  // along (-1, -1, 0): x - 10 = y = 2 / sqrt(5)
  entries[2].direction = glm::vec3(-1, -1, 0);
  for (const bool use_bvh : {true, false}) {
    SCOPED_TRACE(use_bvh ? "BVH" : "scan");
    const auto got = gpu::run_world_probe(gpu(), s, use_bvh, entries);
    ASSERT_EQ(got[0].hit, 1u);
    EXPECT_EQ(got[0].material, 1u);  // g's "b": the last placed
    ASSERT_EQ(got[1].hit, 1u);
    EXPECT_NEAR(got[1].t, 8, 1e-5);
    EXPECT_NEAR(got[1].normal.x, 1, 1e-5);
    ASSERT_EQ(got[2].hit, 1u);
    EXPECT_NEAR(got[2].t, 4 - 2 / std::sqrt(5.0), 1e-5);
    EXPECT_NEAR(got[2].normal.x, 1 / std::sqrt(17.0), 1e-5);
    EXPECT_NEAR(got[2].normal.y, 4 / std::sqrt(17.0), 1e-5);
  }
}

// A mesh file with vertex normals (smooth shading) and no materials of its own, read from OBJ
// text, under the lesson's normal shading: the GPU blends the same normals as the CPU (no pixel
// more than 2 levels off on lavapipe, Mesa 22.3 and 25).
TEST_F(GpuShapes, ASmoothMeshFromAnObjFileMatchesTheCpu) {
  const test::indexed_mesh m = test::cube_sphere(6, 0.5);
  const std::string plain = test::obj_text(m);
  std::string obj = plain.substr(0, plain.find("\nf ") + 1);  // the positions
  for (const point3& p : m.positions) {
    const vec3 n = glm::normalize(p);
    obj +=
        "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
  }
  for (const auto& f : m.faces) {  // "f a//a b//b c//c": each vertex its own normal
    obj += "f";
    for (const std::uint32_t v : f)
      obj += " " + std::to_string(v + 1) + "//" + std::to_string(v + 1);
    obj += "\n";
  }
  scene s = builtin_scene("seed");
  s.spheres.resize(1);
  s.spheres[0] = sphere(point3(0, -100.5, -1), 100, 0);
  load_mesh_bytes(
      s, obj, "obj", "smooth.obj", "",
      {.material = 0, .placement = make_transform(vec3(1), vec3(0, 1, 0), 20, vec3(0, 0, -1))});
  ASSERT_EQ(s.triangles.size(), m.faces.size());
  ASSERT_GE(s.triangles[0].shading, 0);
  ASSERT_TRUE(s.shading[std::size_t(s.triangles[0].shading)].has_normals());
  s.render.width = 160;
  const image_difference d = gpu_vs_cpu(gpu(), s);
  EXPECT_LE(d.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  EXPECT_GE(d.psnr_db, 50);
  // Smooth, not flat: the same mesh without its normals draws another image.
  scene flat = s;
  flat.shading.clear();
  for (triangle& t : flat.triangles) t.shading = -1;
  EXPECT_GT(compare_images(test::cpu_image(flat), test::cpu_image(s), 2).pixels_over, 500);
}

TEST_F(GpuShapes, BvhGivesTheLinearScansImageOverEveryKindOfObject) {
  scene s = builtin_scene("materials");
  add_box(s, point3(-2, -0.5, -3), point3(-1, 0.7, -2), 1);
  s.quads.push_back({point3(1.2, -0.5, -2), vec3(1, 0, 0.3), vec3(0, 1.2, 0), 4});
  s.quads.push_back(s.quads[0]);  // exactly over the box's front: the later one wins the tie
  s.quads.back().material = 0;
  const test::indexed_mesh m = test::cube_sphere(3, 0.3);
  test::add_triangles(s, m, 2);
  s.render.width = 96;
  s.render.spp = 3;
  const camera cam = test::scene_camera(s);
  auto image = [&](bool bvh) {
    return quantize(gpu::render_gpu(gpu(), cam, s, s.render, {}, {.engine = {.use_bvh = bvh}}), 2);
  };
  EXPECT_EQ(image(true).rgb, image(false).rgb);
}

// Disks in every orientation, some in a group placed by turned, scaled and mirrored instances,
// under the lesson's normal shading: the GPU draws them as the CPU does (the bounds of the test
// of every kind above), its BVH exactly as its linear scan, and without them the picture
// differs (they are drawn at all).
TEST_F(GpuShapes, DisksAndInstancedDisksMatchTheCpuAndTheScan) {
  scene s = builtin_scene("seed");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 12; ++i)
    s.disks.push_back({point3(1.2 * u(rng), 0.4 * u(rng), -1.3 + 0.3 * u(rng)),
                       vec3(u(rng), u(rng), u(rng)), 0.08 + 0.1 * (u(rng) + 1), 0});
  s.disks.push_back(s.disks[2]);  // exactly over disk 2: the later one wins the tie
  object_group g;
  g.name = "coins";
  g.disks = {{point3(0), vec3(0, 1, 0.3), 0.2, 0}, {point3(0.1, 0.05, 0), vec3(1, 0, 0), 0.15, 0}};
  s.groups.push_back(g);
  s.instances.push_back({0, make_transform(vec3(1), vec3(0, 1, 0), 0, vec3(-0.5, 0.3, -1))});
  s.instances.push_back(
      {0, make_transform(vec3(-1, 1.5, 1), vec3(1, 0, 0), 25, vec3(0.4, 0.3, -1.1))});
  s.render.width = 160;
  const image_difference d = gpu_vs_cpu(gpu(), s);
  EXPECT_LE(d.pixels_over, 160 * 90 / 500) << "of " << 160 * 90;
  EXPECT_GE(d.psnr_db, 50);
  const camera cam = test::scene_camera(s);
  auto image = [&](const scene& x, bool bvh) {
    return quantize(gpu::render_gpu(gpu(), cam, x, x.render, {}, {.engine = {.use_bvh = bvh}}), 2);
  };
  const image_rgb8 with = image(s, true);
  EXPECT_EQ(with.rgb, image(s, false).rgb);
  scene none = s;
  none.disks.clear();
  none.groups.clear();
  none.instances.clear();
  EXPECT_GT(compare_images(image(none, true), with, 2).pixels_over, 100);  // 215 on lavapipe
}

// Rays from random points at the shared edges and vertices of a closed mesh, in float through
// both of the GPU's searches: all hit where they aim.
TEST_F(GpuShapes, RaysAtSharedEdgesAndVerticesOfAClosedMeshAllHitInFloat) {
  const test::indexed_mesh m = test::cube_sphere(6, 1.0);
  scene s;
  s.materials = {{"n", material{}}};
  test::add_triangles(s, m, 0);
  std::vector<gpu::world_probe_entry> entries;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const point3 a = m.positions[f[std::size_t(k)]], b = m.positions[f[std::size_t((k + 1) % 3)]];
      for (const point3& target : {a, 0.5 * (a + b)}) {
        const point3 from =
            glm::normalize(target) * 4.0 + 0.5 * vec3(unit(gen), unit(gen), unit(gen));
        gpu::world_probe_entry e{};
        e.origin = glm::vec3(from);
        e.direction = glm::vec3(target - from);
        entries.push_back(e);
      }
    }
  for (const bool bvh : {true, false}) {
    const auto got = gpu::run_world_probe(gpu(), s, bvh, entries);
    int missed = 0;
    // Hit where aimed, at t = 1 (not on the far side, through a gap), to float rounding.
    for (const auto& e : got) missed += e.hit == 0 || std::abs(e.t - 1.0f) > 1e-4f;
    EXPECT_EQ(missed, 0) << "of " << got.size() << (bvh ? " through the BVH" : " in a scan");
  }
}

}  // namespace
}  // namespace rtvk
