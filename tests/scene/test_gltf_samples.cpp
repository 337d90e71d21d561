// The Khronos glTF feature-test models render as their own READMEs say a pass looks, on the CPU
// (tests/gltf_samples.h says how they are drawn; tests/gpu/test_gpu_gltf_samples.cpp holds the
// device's images to the same checks). Each check counts pixels of the colors the README names:
// green checks where a pass shows them, no red X where a failure would show one.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gltf_samples.h"
#include "image_io.h"

namespace rtvk {
namespace test {
namespace {

std::string at_least(int got, int want, const std::string& what) {
  return got >= want ? ""
                     : what + ": " + std::to_string(got) +
                           " pixels, want >= " + std::to_string(want) + "; ";
}
std::string at_most(int got, int want, const std::string& what) {
  return got <= want ? ""
                     : what + ": " + std::to_string(got) +
                           " pixels, want <= " + std::to_string(want) + "; ";
}

// TextureSettingsTest: every "Test" box a green check (the clamp ones solid green); a wrong wrap
// mode or a doubleSided flag not respected shows a red X (or a solid red box) instead.
std::string texture_settings(const sample_view&, const framebuffer& fb) {
  return at_most(count(fb, strongly_red), 3, "red (an X: wrap mode or doubleSided)") +
         at_least(count(fb, strongly_green), 300, "green (checks)");
}

// VertexColorTest: the top row's checks are multiplied by red, green and blue vertex colors, which
// zero the cyan, magenta and yellow X drawn in the other channels.
std::string vertex_colors(const sample_view&, const framebuffer& fb) {
  return at_most(
             count(fb, strongly_cyan) + count(fb, strongly_magenta) + count(fb, strongly_yellow), 3,
             "cyan, magenta or yellow (an X: COLOR_0 not applied)") +
         at_least(count(fb, strongly_red), 150, "red (checks)") +
         at_least(count(fb, strongly_green), 150, "green (checks)");
}

// Whether a color's channels marked 1 in `hue` are each more than twice every other channel
// (the tinted texels are not pure: the red square is orange, the blue one has some green).
color_test leads(color hue) {
  return [hue](const color& c) {
    double low = 0, high = INFINITY;
    for (int k = 0; k < 3; ++k)
      (hue[k] > 0 ? high : low) = hue[k] > 0 ? std::min(high, c[k]) : std::max(low, c[k]);
    return high > 0.05 && high > 2 * low;
  };
}

// TextureCoordinateTest: four squares share one image, each tinted its own color.
std::string texture_coordinates(const sample_view& v, const framebuffer& fb) {
  const std::pair<point3, color_test> quadrants[] = {
      {v.center + 0.4 * v.half * (v.up - v.right), leads({1, 1, 0})},
      {v.center + 0.4 * v.half * (v.up + v.right), leads({1, 0, 0})},
      {v.center - 0.4 * v.half * (v.up + v.right), leads({0, 0, 1})},
      {v.center + 0.4 * v.half * (v.right - v.up), leads({0, 1, 0})}};
  const char* names[] = {"top left yellow", "top right red", "bottom left blue",
                         "bottom right green"};
  std::string out;
  for (int k = 0; k < 4; ++k) {
    const auto [x, y] = pixel_of(v, quadrants[k].first);
    out += at_least(count(fb, quadrants[k].second, x, y, 4), 60, names[k]);
  }
  return out;
}

// TextureTransformTest: the top row's offsets show green U, blue V and cyan UV squares (yellow
// where an offset is not applied); below, each arrow points at its green marker (at the yellow
// one where the transform is not applied, at the red one where the rotation turns backwards).
std::string texture_transforms(const sample_view& v, const framebuffer& fb) {
  const auto at = [&](double x, double y) { return pixel_of(v, point3(x, y, 0)); };
  std::string out;
  int yellow = 0;
  for (double x : {-1.1, 0.0, 1.1}) {
    const auto [i, j] = at(x, 0.55);
    yellow += count(fb, strongly_yellow, i, j, 10);
  }
  out += at_most(yellow, 3, "yellow in the top row (an offset not applied)");
  const auto [gi, gj] = at(-1.1, 0.55);
  const auto [bi, bj] = at(0.0, 0.55);
  const auto [ci, cj] = at(1.1, 0.55);
  out += at_least(count(fb, strongly_green, gi, gj, 6), 60, "green U");
  out += at_least(count(fb, strongly_blue, bi, bj, 6), 60, "blue V");
  out += at_least(count(fb, strongly_cyan, ci, cj, 6), 60, "cyan UV");
  // Each arrow's tip: where it ends in a correct render (measured; the markers sit 0.1 to 0.2
  // beyond), a little back along the arrow, dark.
  const std::pair<glm::dvec2, const char*> tips[] = {
      {{-1.1 - 0.16, -0.55 - 0.30}, "rotation's arrow toward its green marker"},
      {{0.0 - 0.13, -0.55 + 0.10}, "scale's arrow toward its green marker"},
      {{1.1 - 0.14, -0.55 - 0.12}, "all's arrow toward its green marker"}};
  for (const auto& [p, what] : tips) {
    const auto [i, j] = at(p.x, p.y);
    out += at_least(count(fb, dark, i, j, 2), 3, what);
  }
  // Where the arrow ends untransformed (measured: the same spot of each quad, whose markers
  // the README calls yellow), light in each quad.
  for (const auto& [x, what] : {std::pair(-1.1, "rotation's arrow untransformed"),
                                std::pair(0.0, "scale's arrow untransformed"),
                                std::pair(1.1, "all's arrow untransformed")}) {
    const auto [i, j] = at(x + 0.12, -0.55 - 0.145);
    out += at_most(count(fb, dark, i, j, 2), 0, what);
  }
  return out;
}

// TwoSidedPlane: doubleSided, so its wood shows from above and from below alike.
std::string two_sided(const sample_view& v, const framebuffer& fb) {
  const auto [x, y] = pixel_of(v, v.center);
  const auto wood = [](const color& c) { return c.r > 0.05 && c.r > 1.5 * c.b && c.r > c.g; };
  return at_least(count(fb, wood, x, y, 30), 61 * 61 * 9 / 10, "wood in the middle");
}

// MultiUVTest: its emissive texture reads TEXCOORD_1, which puts the glTF logo (green on black)
// on every face over its base color; the first set would put "Multiple UVs not supported" there
// in white, which added to any base color leaves no channel below 1.
std::string multi_uv(const sample_view& v, const framebuffer& fb) {
  const auto white = [](const color& c) { return std::min({c.r, c.g, c.b}) > 1.0; };
  const auto logo = [](const color& c) { return c.g > 1.1 && c.g > c.r + 0.15 && c.b < 0.95; };
  const auto [x, y] = pixel_of(v, v.center);
  return at_most(count(fb, white), 3, "white (the first set's text)") +
         at_least(count(fb, logo, x, y, 40), 100, "the logo's green");
}

}  // namespace

std::vector<sample_case> sample_cases() {
  const vec3 front(0, 0, 1), up(0, 1, 0);
  return {
      {"TextureSettingsTest",
       {sample_scene("TextureSettingsTest/TextureSettingsTest.glb", front, up, 160)},
       texture_settings},
      {"VertexColorTest",
       {sample_scene("VertexColorTest/VertexColorTest.glb", front, up)},
       vertex_colors},
      {"TextureCoordinateTest",
       {sample_scene("TextureCoordinateTest/TextureCoordinateTest.glb", front, up, 64)},
       texture_coordinates},
      {"TextureTransformTest",
       {sample_scene("TextureTransformTest/TextureTransformTest.gltf", front, up, 160)},
       texture_transforms},
      {"TwoSidedPlane",
       {sample_scene("TwoSidedPlane/TwoSidedPlane.gltf", up, vec3(0, 0, -1), 96),
        sample_scene("TwoSidedPlane/TwoSidedPlane.gltf", -up, vec3(0, 0, 1), 96)},
       two_sided},
      {"OrientationTest", orientation_views(), orientation},
      {"AlphaModes", {alpha_modes_view()}, alpha_modes},
      {"MultiUVTest",
       {sample_scene("MultiUVTest/MultiUVTest.glb", vec3(1, 1, 2), up, 96)},
       multi_uv},
  };
}

namespace {

// Writes each view's image where RTVK_SAMPLES_DUMP names a folder (to look at a failure).
void dump(const std::string& name, std::size_t k, const sample_view& v, const framebuffer& fb);

TEST(GltfSamples, EachFeatureTestModelRendersAsItsReadmeSaysAPassLooks) {
  for (const sample_case& c : sample_cases())
    for (std::size_t k = 0; k < c.views.size(); ++k) {
      const sample_view& v = c.views[k];
      const framebuffer fb = render_cpu(scene_camera(v.s), v.s, v.s.render);
      dump(c.name, k, v, fb);
      EXPECT_EQ(c.check(v, fb), "") << c.name << ", view " << k;
    }
}

// MultiUVTest's material reads TEXCOORD_0 for its base color and TEXCOORD_1 for its emissive
// texture: every triangle carries both, the second set in the logo's corner of the image (glTF's
// [0, 0.25] square, v flipped to rtvk's), the first spread over the image. A model of one set
// (TextureCoordinateTest) carries no second one.
TEST(GltfSamples, TheEmissiveTexturesOwnSetIsEachTrianglesSecondSet) {
  const scene multi = mesh_scene(gltf_samples / "MultiUVTest/MultiUVTest.glb");
  int without = 0, outside = 0;
  double widest = 0;
  for (const triangle& t : multi.triangles) {
    const triangle_shading& sh = multi.shading.at(std::size_t(t.shading));
    without += !sh.has_uv1 || !sh.has_uv;
    for (std::size_t k = 0; k < 3; ++k) {
      outside += sh.uv1[k].x < 0 || sh.uv1[k].x > 0.25 || sh.uv1[k].y < 0.75 || sh.uv1[k].y > 1;
      widest = std::max(widest, sh.uv[k].x);
    }
  }
  EXPECT_EQ(multi.triangles.size(), 12u);
  EXPECT_EQ(without, 0);
  EXPECT_EQ(outside, 0);
  EXPECT_GT(widest, 0.7);  // the first set reaches the image's third column
  const scene one = mesh_scene(gltf_samples / "TextureCoordinateTest/TextureCoordinateTest.glb");
  for (const triangle_shading& sh : one.shading) EXPECT_FALSE(sh.has_uv1);
}

void dump(const std::string& name, std::size_t k, const sample_view& v, const framebuffer& fb) {
  const char* folder = std::getenv("RTVK_SAMPLES_DUMP");
  if (!folder) return;
  write_image(quantize(fb, v.s.render.encoding()),
              std::filesystem::path(folder) / (name + std::to_string(k) + ".png"));
}

}  // namespace
}  // namespace test
}  // namespace rtvk
