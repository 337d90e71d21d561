// The surface features beyond the books on the CPU reference, against answers known in closed
// form (tests/surface_scenes.h): emission, vertex colors, alpha mask and blend, back-face
// culling; and the AOVs' first surface that counts.
#include <gtest/gtest.h>

#include <cmath>

#include "render_aov.h"
#include "render_helpers.h"
#include "scatter.h"
#include "surface_scenes.h"

namespace rtvk {
namespace {

framebuffer render_surface(const scene& s) {
  return render_cpu(test::scene_camera(s), s, s.render);
}

// Every pixel is exactly `want`.
void expect_all_pixels(const framebuffer& f, const color& want) {
  int wrong = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) wrong += f.at(x, y) != want;
  EXPECT_EQ(wrong, 0) << "pixels other than (" << want.x << ", " << want.y << ", " << want.z
                      << "), e.g. " << f.at(0, 0).x << ", " << f.at(0, 0).y << ", " << f.at(0, 0).z;
}

// A flat surface emitting E is seen as E plus its albedo, exactly; a black lambertian one as E
// alone (what it reflects of the black sky adds nothing); an emission texture multiplies E.
TEST(Surface, EmissionAddsExactlyWhatIsSeenDirectly) {
  material front = test::flat_material(color(0.125, 0.25, 0.375));
  front.emission = color(0.5, 0.25, 2.0);
  expect_all_pixels(render_surface(test::surface_scene(front, test::flat_material(color(0)))),
                    color(0.625, 0.5, 2.375));

  material black;
  black.type = material_type::lambertian;
  black.albedo = color(0.5);
  black.emission = color(0.5, 0.25, 2.0);
  scene alone = test::surface_scene(black, test::flat_material(color(0)));
  alone.quads.pop_back();  // nothing else to see
  expect_all_pixels(render_surface(alone), color(0.5, 0.25, 2.0));

  scene textured = test::surface_scene(front, test::flat_material(color(0)));
  textured.textures.push_back(test::row_texture({0xff000000u | 51u | (102u << 8) | (255u << 16)}));
  textured.materials[0].m.emission_texture = 0;
  const framebuffer f = render_surface(textured);
  const color want(0.125 + 0.5 * 51 / 255.0, 0.25 + 0.25 * 102 / 255.0, 0.375 + 2.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f.at(3, 11)[c], want[c], 1e-12);
}

// The vertex colors blend across the triangles: each corner pixel shows its corner's color, and
// every pixel the blend at its point of the plane. A scene of flat materials draws one sample
// through each pixel's corner point (the lesson's u = i / (width - 1), no jitter), so the answer
// is exact up to double's rounding.
TEST(Surface, VertexColorsInterpolateAcrossTheTriangles) {
  const framebuffer f = render_surface(test::vertex_color_scene());
  const int n = f.width();
  int wrong = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double px = -1 + 2.0 * x / (n - 1), py = 1 - 2.0 * y / (n - 1);  // row 0 at the top
      const color want = test::vertex_color_at(px, py);
      for (int c = 0; c < 3; ++c) wrong += std::abs(f.at(x, y)[c] - want[c]) > 1e-9;
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(f.at(0, n - 1), color(1, 0, 0));      // bottom left: red
  EXPECT_EQ(f.at(n - 1, n - 1), color(0, 1, 0));  // bottom right: green
  EXPECT_EQ(f.at(n - 1, 0), color(0, 0, 1));      // top right: blue
  EXPECT_EQ(f.at(0, 0), color(1, 1, 1));          // top left: white
}

// The emission texture reads the second texture coordinates where a triangle has them, the color
// the first: red + green where it has them, 2 * red where it has not (tests/surface_scenes.h).
// Off the diagonal, where the two triangles meet, every pixel is exact.
TEST(Surface, TheEmissionTextureReadsTheSecondTextureCoordinates) {
  const framebuffer f = render_surface(test::second_uv_scene());
  const int n = f.width();
  int wrong = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      if (x + y == n - 1) continue;      // on the diagonal: either triangle
      const bool first = x + y > n - 1;  // x >= y in the plane (row 0 at the top)
      wrong += f.at(x, y) != (first ? color(1, 1, 0) : color(2, 0, 0));
    }
  EXPECT_EQ(wrong, 0) << "e.g. bottom right " << f.at(n - 1, n - 1).x << ", "
                      << f.at(n - 1, n - 1).y << "; top left " << f.at(0, 0).x << ", "
                      << f.at(0, 0).y;
}

// A mask whose texture's alpha is 0 on its left half and 255 on its right shows the back quad on
// the left and its own texel on the right, exactly.
TEST(Surface, AMaskShowsWhatIsBehindWhereTheTexturesAlphaIsBelowTheCutoff) {
  material front = test::flat_material(color(1));
  front.alpha = alpha_mode::mask;
  front.alpha_cutoff = 0.5;
  front.texture = 0;
  scene s = test::surface_scene(front, test::flat_material(color(0, 0, 1)));
  s.textures.push_back(test::row_texture({0x000000ffu, 0xff00ff00u}));  // clear red, opaque green
  const framebuffer f = render_surface(s);
  int wrong = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x)
      wrong += f.at(x, y) != (x < f.width() / 2 ? color(0, 0, 1) : color(0, 1, 0));
  EXPECT_EQ(wrong, 0);
}

// A blend of opacity a converges to a * front + (1 - a) * back: each sample sees one or the
// other, so red + blue is 1 in every pixel, and the image's mean red, a binomial share of
// 16 x 16 x 256 samples, lies within 5 standard deviations (sqrt(a (1 - a) / n), 0.0017) of a.
TEST(Surface, ABlendConvergesToTheAlphaBlendOfFrontAndBack) {
  material front = test::flat_material(color(1, 0, 0));
  front.alpha = alpha_mode::blend;
  front.opacity = 0.25;
  scene s = test::surface_scene(front, test::flat_material(color(0, 0, 1)));
  s.render.spp = 256;
  const framebuffer f = render_surface(s);
  double red = 0;
  int not_one = 0;
  for (int y = 0; y < f.height(); ++y)
    for (int x = 0; x < f.width(); ++x) {
      red += f.at(x, y).x;
      not_one += std::abs(f.at(x, y).x + f.at(x, y).z - 1) > 1e-12;
    }
  const double n = double(f.width()) * f.height();
  EXPECT_EQ(not_one, 0);
  EXPECT_NEAR(red / n, 0.25, 5 * std::sqrt(0.25 * 0.75 / (n * s.render.spp)));
  EXPECT_GT(red, 0);  // not all passed
}

// cull_back: seen from the front the surface; from the back what is behind it. A dielectric's
// back counts all the same (a ray leaves glass through its back).
TEST(Surface, CullBackShowsWhatIsBehindFromTheBackAndTheSurfaceFromTheFront) {
  material front = test::flat_material(color(1, 0, 0));
  front.cull_back = true;
  const material back = test::flat_material(color(0, 0, 1));
  expect_all_pixels(render_surface(test::surface_scene(front, back)), color(1, 0, 0));
  expect_all_pixels(render_surface(test::surface_scene(front, back, true)), color(0, 0, 1));
  EXPECT_TRUE(surface_counts(RTVK_MATERIAL_DIELECTRIC, RTVK_MATERIAL_CULL_BACK, false, 1, 0.5, 0));
  EXPECT_FALSE(surface_counts(RTVK_MATERIAL_LAMBERTIAN, RTVK_MATERIAL_CULL_BACK, false, 1, 0.5, 0));
}

// The AOVs describe the first surface that counts: through a mask's clear half and a culled back
// the back quad (object 1, two units away at the center), else the front (object 0, one unit).
TEST(Surface, TheAovsSeeTheFirstSurfaceThatCounts) {
  material front = test::flat_material(color(1));
  front.alpha = alpha_mode::mask;
  front.texture = 0;
  scene s = test::surface_scene(front, test::flat_material(color(0, 0, 1)));
  s.textures.push_back(test::row_texture({0x000000ffu, 0xff00ff00u}));
  const camera cam = test::scene_camera(s);
  const std::vector<gpu::gpu_aov> a = render_aov_cpu(cam, s, {0, 0, 16, 16, 0, 1}, 1);
  EXPECT_EQ(a[8 * 16 + 2].object, 1u);
  EXPECT_EQ(a[8 * 16 + 13].object, 0u);
  EXPECT_NEAR(a[8 * 16 + 2].depth, 2, 1e-6);
  EXPECT_NEAR(a[8 * 16 + 13].depth, 1, 1e-6);
  EXPECT_EQ(a[8 * 16 + 2].albedo, glm::vec3(0, 0, 1));

  material culled = test::flat_material(color(1));
  culled.cull_back = true;
  const scene b = test::surface_scene(culled, test::flat_material(color(0, 0, 1)), true);
  const std::vector<gpu::gpu_aov> c = render_aov_cpu(cam, b, {0, 0, 16, 16, 0, 1}, 1);
  EXPECT_EQ(c[8 * 16 + 8].object, 1u);
  // the lesson's ray through pixel (8, 8), at u = 8 / 15 and v = 7 / 15 of the view: its two
  // segments, to the culled quad and on to the back one, sum to the whole way 2 units deep
  EXPECT_NEAR(c[8 * 16 + 8].distance, 2 * std::hypot(1, 1.0 / 15, 1.0 / 15), 1e-5);
}

}  // namespace
}  // namespace rtvk
