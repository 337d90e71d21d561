// Object ids of --aov object-id: one per object as the scene names it, whatever the primitives.
#include <gtest/gtest.h>

#include "aov_output.h"
#include "object_ids.h"
#include "scene.h"

namespace rtvk {
namespace {

TEST(ObjectIds, BoxesMeshesAndInstancesAreOneObjectEach) {
  scene s;
  s.materials = {{"m", material{}}};
  s.spheres = {sphere(point3(0, 0, 0), 1), sphere(point3(3, 0, 0), 1)};
  s.quads.push_back({point3(0, 0, -5), vec3(1, 0, 0), vec3(0, 1, 0), 0});
  add_box(s, point3(-1, -1, -1), point3(1, 1, 1), 0);  // quads 1..6
  for (int k = 0; k < 5; ++k)  // triangles 0, 1: a "mesh"; 2..4 alone
    s.triangles.push_back({{point3(k, 0, 0), point3(k + 1, 0, 0), point3(k, 1, 0)}, 0});
  s.compounds.push_back({true, 0, 2});
  s.groups.push_back({});
  s.instances = {{0, {}}, {0, {}}};
  const object_ids ids(s);
  // Scan-order keys: spheres 0, 1; quads 2..8; triangles 9..13.
  EXPECT_EQ(ids.of(0, 0), 1u);
  EXPECT_EQ(ids.of(1, 0), 2u);
  EXPECT_EQ(ids.of(2, 0), 3u);  // the lone quad
  for (std::uint32_t q = 3; q <= 8; ++q) EXPECT_EQ(ids.of(q, 0), 4u) << q;  // the box
  EXPECT_EQ(ids.of(9, 0), 5u);  // the mesh
  EXPECT_EQ(ids.of(10, 0), 5u);
  EXPECT_EQ(ids.of(11, 0), 6u);
  EXPECT_EQ(ids.of(13, 0), 8u);
  EXPECT_EQ(ids.of(0, 1), 9u);  // instance 0, any object of its group
  EXPECT_EQ(ids.of(5, 1), 9u);
  EXPECT_EQ(ids.of(0, 2), 10u);
  EXPECT_EQ(ids.count(), 10u);
  EXPECT_EQ(ids.of(14, 0), 0u);  // keys the scene lacks: nothing
  EXPECT_EQ(ids.of(0, 3), 0u);
}

// --backend both lets ids differ only where the CPU's own id image changes (a ray grazing two
// surfaces); a difference inside an object is a real disagreement.
TEST(ObjectIds, TheBothBackendsCheckAllowsDifferencesOnlyOnEdges) {
  scene s;
  s.materials = {{"m", material{}}};
  s.spheres = {sphere(point3(0, 0, 0), 1), sphere(point3(3, 0, 0), 1)};
  const object_ids ids(s);
  // A 6x1 strip: object 0 on the left three pixels, object 1 on the right three.
  std::vector<gpu::gpu_aov> cpu(6);
  for (std::size_t k = 0; k < 6; ++k) cpu[k] = {{}, 1, {}, 1, k < 3 ? 0u : 1u, 0, 0, 1};
  std::vector<gpu::gpu_aov> gpu = cpu;
  EXPECT_TRUE(aovs_agree(gpu, cpu, ids, 6, ""));
  gpu[2].object = 1;  // at the edge
  EXPECT_TRUE(aovs_agree(gpu, cpu, ids, 6, ""));
  gpu[0].object = 1;  // inside object 0
  EXPECT_FALSE(aovs_agree(gpu, cpu, ids, 6, ""));
  gpu = cpu;
  gpu[4].distance = 1.001f;  // the same object, farther
  EXPECT_FALSE(aovs_agree(gpu, cpu, ids, 6, ""));
}

}  // namespace
}  // namespace rtvk
