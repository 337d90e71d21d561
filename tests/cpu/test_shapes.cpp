// Quads, boxes and triangles on the CPU: known answers worked by hand, watertight closed meshes,
// and the BVH finding exactly what the lesson's linear scan finds over every kind of object.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "bvh_world.h"
#include "hittable_quad.h"
#include "hittable_triangle.h"
#include "mesh_helpers.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "world.h"

namespace rtvk {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The square [-1, 1]^2 at z = 0, facing +z: a ray straight down from (0.5, 0.25, 5) meets it at
// t = 5, at plane coordinates alpha = (0.5 + 1) / 2 = 0.75 and beta = (0.25 + 1) / 2 = 0.625.
TEST(Quad, HitsWhereWorkedByHand) {
  const quad q{point3(-1, -1, 0), vec3(2, 0, 0), vec3(0, 2, 0), 0};
  const quad_geometry g = q.geometry();
  EXPECT_EQ(g.normal, vec3(0, 0, 1));
  EXPECT_EQ(g.D, 0);
  EXPECT_EQ(g.w, vec3(0, 0, 0.25));  // cross(u, v) / |cross(u, v)|^2 = (0, 0, 4) / 16
  double t;
  real2 uv;
  ASSERT_TRUE(hit_quad(g, ray(point3(0.5, 0.25, 5), vec3(0, 0, -1)), 0.001, inf, t, uv));
  EXPECT_EQ(t, 5);
  EXPECT_EQ(uv, real2(0.75, 0.625));
  hit_record rec{};
  record_quad_hit(g, 0, ray(point3(0.5, 0.25, 5), vec3(0, 0, -1)), t, rec);
  EXPECT_TRUE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, 1));
  EXPECT_EQ(rec.p, point3(0.5, 0.25, 0));
  // From behind: the same point, the back face, the normal turned toward the ray.
  ASSERT_TRUE(hit_quad(g, ray(point3(0.5, 0.25, -2), vec3(0, 0, 2)), 0.001, inf, t, uv));
  EXPECT_EQ(t, 1);
  record_quad_hit(g, 0, ray(point3(0.5, 0.25, -2), vec3(0, 0, 2)), t, rec);
  EXPECT_FALSE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, -1));
  // Its edges are inside (alpha = 1 exactly); beyond them, outside; parallel rays miss; a hit
  // beyond t_max is no hit.
  EXPECT_TRUE(hit_quad(g, ray(point3(1, 0, 1), vec3(0, 0, -1)), 0.001, inf, t, uv));
  EXPECT_EQ(uv.x, 1);
  EXPECT_FALSE(hit_quad(g, ray(point3(1.0001, 0, 1), vec3(0, 0, -1)), 0.001, inf, t, uv));
  EXPECT_FALSE(hit_quad(g, ray(point3(0, 0, 1), vec3(1, 0, 0)), 0.001, inf, t, uv));
  EXPECT_FALSE(hit_quad(g, ray(point3(0, 0, 5), vec3(0, 0, -1)), 0.001, 4.9, t, uv));
}

// The triangle (0,0,0), (1,0,0), (0,1,0), facing +z: the ray down through (0.25, 0.25) meets it
// at t = 1 with weights 1 - 0.25 - 0.25 = 0.5 for a, 0.25 for b and c.
TEST(Triangle, HitsWhereWorkedByHand) {
  const point3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const ray down(point3(0.25, 0.25, 1), vec3(0, 0, -1));
  double t;
  real3 w;
  ASSERT_TRUE(hit_triangle(a, b, c, down, shear_ray(down), 0.001, inf, t, w));
  EXPECT_EQ(t, 1);
  EXPECT_EQ(w, real3(0.5, 0.25, 0.25));
  hit_record rec{};
  record_triangle({a, b, c}, nullptr, 3, down, shear_ray(down), t, rec);
  EXPECT_TRUE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, 1));
  EXPECT_EQ(rec.material, 3u);
  // From below (the back), along a slanted direction: t scales with the direction's length.
  const ray up(point3(0.25, 0.25, -2), vec3(0, 0, 4));
  ASSERT_TRUE(hit_triangle(a, b, c, up, shear_ray(up), 0.001, inf, t, w));
  EXPECT_EQ(t, 0.5);
  record_triangle({a, b, c}, nullptr, 0, up, shear_ray(up), t, rec);
  EXPECT_FALSE(rec.front_face);
  EXPECT_EQ(rec.normal, vec3(0, 0, -1));
  // Outside, past the hypotenuse; parallel; behind the origin.
  const ray out(point3(0.6, 0.6, 1), vec3(0, 0, -1));
  EXPECT_FALSE(hit_triangle(a, b, c, out, shear_ray(out), 0.001, inf, t, w));
  const ray flat(point3(-1, 0.2, 0), vec3(1, 0, 0));
  EXPECT_FALSE(hit_triangle(a, b, c, flat, shear_ray(flat), 0.001, inf, t, w));
  const ray away(point3(0.25, 0.25, 1), vec3(0, 0, 1));
  EXPECT_FALSE(hit_triangle(a, b, c, away, shear_ray(away), 0.001, inf, t, w));
}

// Smooth shading: the vertex normals blended by the hit's weights, turned to the ray's side.
TEST(Triangle, SmoothNormalsBlendByBarycentricWeights) {
  const triangle tri{{point3(0, 0, 0), point3(1, 0, 0), point3(0, 1, 0)}, 0};
  triangle_shading shading;
  shading.normal = {vec3(0, 0, 1), vec3(1, 0, 0), vec3(0, 1, 0)};
  const hittable_triangle h(tri, &shading);
  hit_record rec{};
  ASSERT_TRUE(h.hit(ray(point3(0.25, 0.25, 1), vec3(0, 0, -1)), 0.001, inf, rec));
  // 0.5 (0,0,1) + 0.25 (1,0,0) + 0.25 (0,1,0), normalized.
  const vec3 expected = glm::normalize(vec3(0.25, 0.25, 0.5));
  EXPECT_NEAR(glm::length(rec.normal - expected), 0, 1e-15);
}

// The book's box: six quads, each facing out, covering the box's surface.
TEST(Box, IsTheBooksSixQuadsFacingOut) {
  scene s;
  add_box(s, point3(1, 2, 3), point3(-1, 0, 0), 0);
  ASSERT_EQ(s.quads.size(), 6u);
  for (const quad& q : s.quads) {
    const point3 center = q.Q + 0.5 * (q.u + q.v);
    // Each face's normal points away from the box's center (0, 1, 1.5).
    EXPECT_GT(glm::dot(q.geometry().normal, center - point3(0, 1, 1.5)), 0);
  }
  // Front (z = 3): the book's first quad, Q = (min.x, min.y, max.z), u = dx, v = dy.
  EXPECT_EQ(s.quads[0].Q, point3(-1, 0, 3));
  EXPECT_EQ(s.quads[0].u, vec3(2, 0, 0));
  EXPECT_EQ(s.quads[0].v, vec3(0, 2, 0));
}

// Found in review: a mirroring transform turned boxes inside out (their quads' fronts faced in).
TEST(Box, AMirroredBoxStillFacesOut) {
  scene s;
  add_box(s, point3(1, 2, 3), point3(-1, 0, 0), 0,
          make_transform(vec3(-1, 1, 1), vec3(0, 1, 0), 0, vec3(0)));
  for (const quad& q : s.quads) {
    const point3 center = q.Q + 0.5 * (q.u + q.v);
    EXPECT_GT(glm::dot(q.geometry().normal, center - point3(0, 1, 1.5)), 0);
  }
}

TEST(Transform, ScalesRotatesAndTranslatesInThatOrder) {
  // Scale x by 2, a quarter turn about +y (x goes to -z), then up by 1.
  const transform t = make_transform(vec3(2, 1, 1), vec3(0, 1, 0), 90, vec3(0, 1, 0));
  EXPECT_EQ(t.apply_point(point3(1, 0, 0)), point3(0, 1, -2));
  EXPECT_EQ(t.apply_vector(vec3(0, 0, 1)), vec3(1, 0, 0));
  EXPECT_FALSE(t.uniform_scale().has_value());
  const transform r = make_transform(vec3(3), vec3(1, 1, 1), 37, vec3(5));
  ASSERT_TRUE(r.uniform_scale().has_value());
  EXPECT_NEAR(*r.uniform_scale(), 3, 1e-12);
  // Normals go through the inverse transpose: a plane x = y scaled by 2 along x.
  const transform stretch = make_transform(vec3(2, 1, 1), vec3(0, 1, 0), 0, vec3(0));
  const vec3 n = stretch.apply_normal(glm::normalize(vec3(1, -1, 0)));
  EXPECT_NEAR(glm::dot(n, stretch.apply_vector(vec3(1, 1, 0))), 0, 1e-15);  // still normal
  EXPECT_TRUE(degenerate(make_transform(vec3(1, 0, 1), vec3(0, 1, 0), 0, vec3(0))).has_value());
  EXPECT_FALSE(degenerate(r).has_value());
}

// Rays aimed exactly at the shared edges and vertices of a closed mesh, from outside, all hit it
// there (not the far side, through a gap): through the lesson's list, through the BVH, along
// axis-parallel rays (whose edge functions are exactly zero on edges, where a test that counted
// zero as outside would let them through), and from random points toward edge midpoints and
// vertices.
std::vector<ray> rays_at_edges_and_vertices(const test::indexed_mesh& m, std::uint32_t seed) {
  std::vector<ray> rays;
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> unit(-1, 1);
  const auto from_outside = [&](const point3& target) {
    vec3 d;
    do d = vec3(unit(gen), unit(gen), unit(gen));
    while (glm::length(d) < 0.1 || glm::length(d) > 1);
    // From a point 4 units off, on the side the target faces.
    vec3 out = glm::normalize(target) * 4.0 + d;
    rays.push_back(ray(out, target - out));
  };
  for (const auto& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const point3 a = m.positions[f[std::size_t(k)]], b = m.positions[f[std::size_t((k + 1) % 3)]];
      from_outside(0.5 * (a + b));
      from_outside(a);
      // Axis-parallel, through the edge's midpoint, from beyond it along its dominant axis.
      const point3 mid = 0.5 * (a + b);
      const vec3 n = glm::normalize(mid);
      const int axis = std::abs(n.x) > std::abs(n.y) ? (std::abs(n.x) > std::abs(n.z) ? 0 : 2)
                                                     : (std::abs(n.y) > std::abs(n.z) ? 1 : 2);
      vec3 dir(0);
      dir[axis] = n[axis] > 0 ? -1 : 1;
      rays.push_back(ray(mid - 5.0 * dir, dir));
    }
  return rays;
}

TEST(Watertight, RaysAtSharedEdgesAndVerticesOfAClosedMeshAllHit) {
  const test::indexed_mesh m = test::cube_sphere(6, 1.0);
  scene s;
  s.materials = {{"n", material{}}};
  test::add_triangles(s, m, 0);
  const std::vector<ray> rays = rays_at_edges_and_vertices(m, 7);
  const hittable_list list = make_world(s);
  const std::unique_ptr<hittable> tree = make_accelerated_world(s, true);
  int missed_list = 0, missed_tree = 0;
  for (const ray& r : rays) {
    // The aimed point is where the ray's t is 1 (the axis-parallel rays: 5, their unit length).
    const double aimed = glm::length(r.direction) > 1.5 ? 1.0 : 5.0;
    hit_record rec{};
    missed_list += !list.hit(r, 0.001, inf, rec) || std::abs(rec.t - aimed) > 1e-9;
    missed_tree += !tree->hit(r, 0.001, inf, rec) || std::abs(rec.t - aimed) > 1e-9;
  }
  EXPECT_EQ(missed_list, 0) << "of " << rays.size();
  EXPECT_EQ(missed_tree, 0) << "of " << rays.size();
}

// A scene of every kind: spheres, a box, quads and a closed mesh, some overlapping exactly.
scene mixed_scene() {
  scene s = builtin_scene("materials");
  s.name = "mixed";
  add_box(s, point3(-2, -0.5, -3), point3(-1, 0.7, -2), 1,
          make_transform(vec3(1), vec3(0, 1, 0), 15, vec3(0)));
  s.quads.push_back({point3(1.2, -0.5, -2), vec3(1, 0, 0.3), vec3(0, 1.2, 0), 4});
  // A quad exactly over the box's front face, a later object: it must win the tie.
  s.quads.push_back(s.quads[0]);
  s.quads.back().material = 0;
  const test::indexed_mesh m = test::cube_sphere(4, 0.35);
  for (const auto& f : m.faces)
    s.triangles.push_back(
        {{m.positions[f[0]] + vec3(0.3, -0.15, -0.4), m.positions[f[1]] + vec3(0.3, -0.15, -0.4),
          m.positions[f[2]] + vec3(0.3, -0.15, -0.4)},
         2});
  return s;
}

TEST(Accel, BvhGivesTheLinearScansImageOverEveryKindOfObject) {
  scene s = mixed_scene();
  s.render.width = 96;
  s.render.spp = 3;
  const camera cam = test::scene_camera(s);
  auto image = [&](engine_options e) { return quantize(render_cpu(cam, s, s.render, {}, e), 2); };
  const image_rgb8 reference = image({.use_bvh = false, .threads = 1});
  EXPECT_EQ(image({.use_bvh = true, .threads = 1}).rgb, reference.rgb);
  EXPECT_EQ(image({.use_bvh = true, .threads = 3}).rgb, reference.rgb);
}

}  // namespace
}  // namespace rtvk
