// The tangent at a hit on the GPU (world.glsl through scene_buffers.glsl's tangents buffer) and
// normal_map.h's GLSL compilation, held to the analytic tangent and to the C++ compilation.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_fixture.h"
#include "mesh_tangents.h"
#include "normal_map.h"
#include "probe.h"
#include "tangent_helpers.h"

namespace rtvk {
namespace {

class GpuTangents : public test::GpuTest {};

// The generated grid (tangents U made unit, w = +1), shaded as the lesson's normals: the probe
// needs no pbr material, only the tangents it left.
scene gpu_tangent_grid() {
  scene s;
  s.materials.push_back({"mapped", test::normal_mapped_pbr()});
  test::add_uv_grid(s, test::affine_uv{}, 4, false);
  generate_tangents(s, 0);
  s.materials[0].m = material{};
  return s;
}

gpu::world_probe_entry tangent_probe_entry(const point3& from, const point3& at,
                                           const vec3& texel) {
  gpu::world_probe_entry e{};
  e.origin = glm::vec3(from);
  e.direction = glm::vec3(at - from);
  e.texel = glm::vec3(texel);
  e.scale = 0.9f;
  return e;
}

// From the front and the back, and through a rotating, stretching instance with and without a
// mirror: the GPU's tangent is the analytic one, and its normal_mapped the C++'s at its hit.
TEST_F(GpuTangents, TheTangentAtAHitAndTheMappedNormalMatchTheAnalyticOnes) {
  const scene flat = gpu_tangent_grid();
  const test::affine_uv f;
  const point3 target = f.origin + 0.7 * f.U + 1.1 * f.V;
  struct probe_case {
    scene s;
    vec3 tangent;  // the analytic tangent, unit
    float w;       // its handedness as the hit sees it
    point3 from, at;
  };
  std::vector<probe_case> cases;
  for (const double side : {1.0, -1.0})
    cases.push_back(
        {flat, glm::normalize(f.U), float(side), target + side * 2.0 * f.normal(), target});
  for (const double mirror : {1.0, -1.0}) {
    scene s;
    s.materials = flat.materials;
    object_group g;
    g.triangles = flat.triangles;
    g.shading = flat.shading;
    s.groups.push_back(g);
    const transform m = make_transform(vec3(mirror * 2, 1, 0.5), vec3(1, 2, 3), 40, vec3(1, 0, 0));
    s.instances.push_back({0, m});
    const point3 at = m.apply_point(target);
    cases.push_back({s, glm::normalize(m.apply_vector(f.U)), float(mirror),
                     at + 2.0 * m.apply_normal(f.normal()), at});
  }
  const vec3 texel(0.8, 0.35, 0.7);
  for (const probe_case& c : cases)
    for (const bool bvh : {true, false}) {
      SCOPED_TRACE(bvh ? "BVH" : "scan");
      const auto got =
          gpu::run_world_probe(gpu(), c.s, bvh, {tangent_probe_entry(c.from, c.at, texel)});
      ASSERT_EQ(got[0].hit, 1u);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[0].tangent[k], c.tangent[k], 1e-5);
      EXPECT_EQ(got[0].tangent.w, c.w);
      // normal_mapped's C++ compilation on the GPU's own hit frame.
      hit_record rec{};
      rec.normal = vec3(got[0].normal);
      rec.tangent = glm::dvec4(got[0].tangent);
      const vec3 want = normal_mapped(rec, texel, 0.9, -glm::normalize(vec3(c.at - c.from)));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[0].mapped[k], want[k], 1e-5);
      EXPECT_GT(glm::distance(want, rec.normal), 0.1);  // the map did bend it
    }
}

// A mesh without tangents: zero on the GPU, and the mapped normal is the hit's own.
TEST_F(GpuTangents, WithoutTangentsTheHitHasNoneAndTheMapChangesNothing) {
  scene s;
  s.materials.push_back({"plain", material{}});
  test::add_uv_grid(s, test::affine_uv{}, 2, false);
  const test::affine_uv f;
  const point3 target = f.origin + 0.7 * f.U + 1.1 * f.V;
  const auto got = gpu::run_world_probe(
      gpu(), s, true, {tangent_probe_entry(target + 2.0 * f.normal(), target, vec3(0.9, 0.1, 1))});
  ASSERT_EQ(got[0].hit, 1u);
  EXPECT_EQ(got[0].tangent, glm::vec4(0));
  EXPECT_EQ(got[0].mapped, got[0].normal);
}

}  // namespace
}  // namespace rtvk
