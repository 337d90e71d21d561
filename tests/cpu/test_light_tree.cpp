// Next-event estimation's light tree (shaders/shared/lights/light_tree.h, host/scene/
// light_tree_builder.cpp): from any shading point its probabilities over the lamps sum to one, the
// probability a draw reports is the one the path's hit of the lamp finds again (the MIS weight's),
// draws land on each lamp as often as that says, and scenes of a thousand small lamps, or lamps
// placed by instances, converge to the plain image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "light_sources.h"
#include "light_tree_builder.h"
#include "light_tree_scenes.h"
#include "nee.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "seed_estimates.h"

namespace rtvk {
namespace {

struct tree_fixture {
  explicit tree_fixture(const scene& s)
      : lamps(scene_lamps(s)),
        nodes(build_light_tree(lamps)),
        table{lamps.data(), uint(lamps.size()), nodes.data()} {}
  std::vector<light_record> lamps;
  std::vector<gpu::gpu_light_node> nodes;
  light_table table;
};

// Random shading points in and around the room, with a random unit normal or none.
struct shading_point {
  point3 p;
  vec3 n;
};
shading_point random_point(std::mt19937_64& gen, int k) {
  std::uniform_real_distribution<double> place(-50, 600), dir(-1, 1);
  const point3 p(place(gen), place(gen), place(gen));
  const vec3 n = k % 4 == 3 ? vec3(0) : glm::normalize(vec3(dir(gen), dir(gen), dir(gen)));
  return {p, n};
}

// Every drawable lamp is one leaf; from any point the leaves' probabilities (their trails
// replayed) sum to one, or to zero where no lamp can light the point.
TEST(LightTree, ItsProbabilitiesOverAllLampsSumToOne) {
  const tree_fixture t(test::many_lamps(1000, true, 8, 1));
  std::vector<int> leaves(t.lamps.size(), 0);
  for (const gpu::gpu_light_node& n : t.nodes)
    if (n.leaf != 0u) ++leaves[n.lamp];
  for (std::size_t k = 0; k < t.lamps.size(); ++k) EXPECT_EQ(leaves[k], 1) << "lamp " << k;
  std::mt19937_64 gen(7);
  for (int i = 0; i < 60; ++i) {
    const shading_point at = random_point(gen, i);
    double sum = 0;
    for (const gpu::gpu_light_node& n : t.nodes)
      if (n.leaf != 0u) sum += light_tree_trail_pmf(t.table, at.p, at.n, n.second);
    EXPECT_NEAR(sum, 1, 1e-9) << "point " << i;
  }
}

// The probability a draw reports is its leaf's, and the one the path that hits the drawn point
// finds (nee_lamp_pdf_at: the point query, then the trail), times the lamp's own density: the two
// strategies' densities agree for every lamp drawn, from random points.
TEST(LightTree, TheHitsProbabilityIsTheDrawsForEveryLamp) {
  const tree_fixture t(test::many_lamps(400, true, 8, 1));
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<int> checked(t.lamps.size(), 0);
  for (int i = 0; i < 40000; ++i) {
    const shading_point at = random_point(gen, i);
    double pmf = 0;
    const uint k = light_tree_draw(t.table, at.p, at.n, u(gen), pmf);
    if (!(pmf > 0)) continue;
    uint leaf = 0;
    for (uint j = 0; j < t.nodes.size(); ++j)
      if (t.nodes[j].leaf != 0u && t.nodes[j].lamp == k) leaf = j;
    ASSERT_EQ(pmf, light_tree_trail_pmf(t.table, at.p, at.n, t.nodes[leaf].second));
    const light_sample ls = lamp_sample(t.lamps[k], at.p, 0, u(gen), u(gen));
    if (!(ls.pdf > 0)) continue;
    // Another lamp may lie in front of the drawn point: the hit finds that one, as a path would.
    uint found = 0;
    ASSERT_TRUE(light_tree_find(t.table, at.p, ls.wi, 0, ls.distance, found));
    if (t.nodes[found].lamp != k) continue;
    const double density = nee_lamp_pdf_at(t.table, at.p, at.n, at.p, ls.wi, 0, ls.distance);
    EXPECT_NEAR(density, pmf * ls.pdf, 1e-9 * pmf * ls.pdf) << "lamp " << k;
    ++checked[k];
  }
  int lamps_checked = 0;
  for (int c : checked) lamps_checked += c > 0;
  EXPECT_GT(lamps_checked, 390);
}

// Draws from one point land on each lamp as often as its probability says: Pearson's chi-square
// over the lamps with an expected count of at least 5 stays under its degrees of freedom plus 5
// standard deviations (sqrt(2 df)).
TEST(LightTree, DrawsFollowTheProbabilitiesByChiSquare) {
  const tree_fixture t(test::many_lamps(300, true, 8, 1));
  const point3 p(278, 100, 278);
  const vec3 n(0, 1, 0);
  std::vector<double> want(t.lamps.size(), 0);
  for (const gpu::gpu_light_node& node : t.nodes)
    if (node.leaf != 0u) want[node.lamp] = light_tree_trail_pmf(t.table, p, n, node.second);
  const int draws = 300000;
  std::vector<int> got(t.lamps.size(), 0);
  for (int i = 0; i < draws; ++i) {
    double pmf = 0;
    const uint k = light_tree_draw(t.table, p, n, (i + 0.5) / draws, pmf);
    ASSERT_EQ(pmf, want[k]);
    ++got[k];
  }
  double chi2 = 0;
  int df = -1;
  for (std::size_t k = 0; k < want.size(); ++k) {
    const double expected = want[k] * draws;
    if (expected < 5) continue;
    chi2 += (got[k] - expected) * (got[k] - expected) / expected;
    ++df;
  }
  ASSERT_GT(df, 100);
  EXPECT_LT(chi2, df + 5 * std::sqrt(2.0 * df)) << "df " << df;
}

using estimate = test::seed_estimate;
estimate over_seeds(const scene& s, int runs) {
  return test::over_seeds(s, runs, 3000);
}

void expect_same_mean(scene s, int plain_spp, int nee_spp) {
  s.render.sampling = sampling_mode::plain;
  s.render.spp = plain_spp;
  const estimate plain = over_seeds(s, 16);
  s.render.sampling = sampling_mode::nee;
  s.render.spp = nee_spp;
  const estimate nee = over_seeds(s, 16);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(nee.mean[c], plain.mean[c], 4 * std::hypot(nee.error[c], plain.error[c]))
        << "channel " << c << ": plain " << plain.mean[c] << " +- " << plain.error[c] << ", nee "
        << nee.mean[c] << " +- " << nee.error[c];
  std::printf("plain %.4f +- %.4f, nee %.4f +- %.4f (green)\n", plain.mean.y, plain.error.y,
              nee.mean.y, nee.error.y);
}

// A thousand small lamps (triangles, spheres and quads, one- and two-sided): the tree's draws and
// the hits' weights are consistent, so next-event estimation's mean is the plain image's.
TEST(LightTreeUnbiased, AThousandSmallLampsConvergeToThePlainImage) {
  scene s = test::many_lamps(1000, true, 12, 1);
  check_sampling(s, s.render, "--sampling");
  expect_same_mean(s, 256, 64);
}

// A group holding a lamp quad and a lamp sphere, placed twice (turned, scaled alike, moved): the
// placed lamps are drawn (group_lamps, world space) and a path that hits one weighs it against
// them, so the mean is the plain image's. A third placement stretches the sphere into an
// ellipsoid: that one is left undrawn, its light found by the paths alone.
TEST(LightTreeUnbiased, LampsPlacedByInstancesConvergeToThePlainImage) {
  const scene s = test::grouped_lamps(12);
  ASSERT_EQ(group_lamps(s).size(), 5u);  // two quads and spheres each, the stretched quad
  const std::vector<light_record> lamps = scene_lamps(s);
  ASSERT_EQ(lamps.size(), 5u);
  // In world space: each placed quad's center (the group's origin) at its instance's offset, each
  // sphere's center where the instance puts (0, -30, 0).
  const std::size_t quads[3] = {1, 3, 4}, spheres[2] = {0, 2};
  for (std::size_t i = 0; i < 3; ++i) {
    const light_record& q = lamps[quads[i]];
    EXPECT_EQ(q.kind, uint(RTVK_LIGHT_QUAD));
    EXPECT_NEAR(glm::length(q.a + 0.5 * (q.u + q.v) - s.instances[i].placement.offset), 0, 1e-9);
  }
  for (std::size_t i = 0; i < 2; ++i) {
    const light_record& sp = lamps[spheres[i]];
    EXPECT_EQ(sp.kind, uint(RTVK_LIGHT_SPHERE));
    EXPECT_NEAR(glm::length(sp.a - s.instances[i].placement.apply_point(point3(0, -30, 0))), 0,
                1e-9);
    EXPECT_NEAR(sp.radius, i == 0 ? 18 : 12, 1e-9);  // scaled by 1.5, then by 1 (mirrored)
  }
  EXPECT_NEAR(lamps[0].a.y, 500 - 45 * std::cos(150 * 3.14159265358979323846 / 180), 1e-9);
  expect_same_mean(s, 256, 64);
}

}  // namespace
}  // namespace rtvk
