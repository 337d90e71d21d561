// The CPU's fast mode (host/fast: the shared kernels in float over the GPU's arrays, packet_bvh
// and Embree finding the hits) against the double-precision reference, which the books' own code
// checks (lesson_reference.h, tests/oracle). The two draw the same numbers per sample, so their
// images differ only where float's rounding turns a path another way: measured floors, as the
// GPU's.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <map>
#include <string>

#include "errors.h"
#include "process.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;

image_rgb8 render_with(const scene& s, cpu_precision precision) {
  engine_options e;
  e.precision = precision;
  return quantize(render_cpu(test::scene_camera(s), s, s.render, {}, e), s.render.encoding());
}

// Reference against fast, within what was measured less test::measured_agreement's margin.
void expect_close(const scene& s, double measured_psnr, int measured_pixels) {
  const image_rgb8 reference = render_with(s, cpu_precision::reference);
  const image_difference d = compare_images(render_with(s, cpu_precision::fast), reference,
                                            monte_carlo_agreement.tolerance);
  const int pixels = reference.width * reference.height;
  const agreement rule =
      test::measured_agreement(measured_psnr, double(measured_pixels) / pixels, pixels);
  std::printf("%s: %.1f dB, %ld pixels over 2 levels\n", s.name.c_str(), d.psnr_db,
              long(d.pixels_over));
  EXPECT_GE(d.psnr_db, rule.min_psnr_db) << s.name;
  EXPECT_LE(d.share_over, rule.max_share) << s.name << ": " << d.pixels_over << " pixels";
}

// What each built-in scene measured at 80 pixels wide and 8 samples (PSNR, pixels more than 2
// levels off); infinity: the same bytes.
const std::map<std::string, std::pair<double, int>> builtin_measured = {
    {"seed", {1e9, 0}},
    {"materials", {1e9, 0}},
    {"book-final", {61.0, 10}},
    {"bouncing-spheres", {64.1, 6}},
    {"quads", {1e9, 0}},
    {"checkered-spheres", {1e9, 0}},
    {"perlin-spheres", {60.2, 5}},
    {"simple-light", {69.2, 0}},
    {"cornell-box", {1e9, 0}},
    {"cornell-smoke", {91.0, 0}},
    {"next-week-final", {62.9, 1}},
    {"rest-of-life-final", {1e9, 0}},
    {"showcase", {88.9, 0}},
};

// Every built-in scene: spheres, moving spheres, quads, textures, media, instances of boxes,
// lamps under the mixture and next-event estimation, PBR materials and the environment map.
TEST(FastMode, EveryBuiltInSceneMatchesTheReference) {
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(builtin_measured.count(name)) << "a new built-in scene: measure it here";
    const scene s = load_scene(name, {});
    scene small = s;
    small.render.width = 80;
    small.render.spp = std::min(s.render.spp, 8);
    const auto [psnr, pixels] = builtin_measured.at(name);
    expect_close(small, psnr, pixels);
  }
}

// docs/scenes' files (those that need no generated mesh): instances placed with every kind of
// transform (forest), disks, PBR layers, punctual lights under an environment map, many lamps
// under next-event estimation, several cameras. views.json, a checker seen at gamma 1 without
// jitter, differs most: the float checker flips cells on their borders, as the GPU's does (the
// fast mode draws the GPU's bytes there, GpuFastMode).
const std::map<std::string, std::pair<double, int>> docs_measured = {
    {"disks.json", {1e9, 0}},       {"environment-sun.json", {66.6, 1}},
    {"forest.json", {88.5, 0}},     {"many-lamps.json", {1e9, 0}},
    {"pbr-layers.json", {88.5, 0}}, {"pbr-spheres.json", {68.7, 3}},
    {"views.json", {36.0, 20}},
};

TEST(FastMode, TheDocsScenesMatchTheReference) {
  const fs::path folder = fs::path(RTVK_TEST_DATA) / ".." / ".." / "docs" / "scenes";
  for (const auto& [file, measured] : docs_measured) {
    SCOPED_TRACE(file);
    scene s = load_scene((folder / file).string(), {});
    s.render.width = 80;
    s.render.spp = std::min(s.render.spp, 8);
    expect_close(s, measured.first, measured.second);
  }
}

// Coincident surfaces: two equal quads, two equal spheres and two equal disks, each pair of two
// flat colors. Every hit on them is an exact tie, which the reference (as hittable_list) and the
// GPU give to the later object in the scene, so only the later colors show. The fast mode's own
// search does the same (packet_bvh); Embree's, which it used before, drew the earlier ones.
const char* const coincident_json =
    R"({"camera":{"lookfrom":[0,0,6],"lookat":[0,0,0],"vfov":60},)"
    R"("render":{"gamma":1,"width":96,"aspect":"1:1","spp":1,"jitter":false,"max_depth":2},)"
    R"("materials":{"r":{"type":"flat","albedo":[1,0,0]},"g":{"type":"flat","albedo":[0,1,0]},)"
    R"("y":{"type":"flat","albedo":[1,1,0]},"c":{"type":"flat","albedo":[0,1,1]},)"
    R"("m":{"type":"flat","albedo":[1,0,1]},"b":{"type":"flat","albedo":[0,0,1]}},)"
    R"("quads":[{"Q":[-3,-3,-1],"u":[6,0,0],"v":[0,6,0],"material":"r"},)"
    R"({"Q":[-3,-3,-1],"u":[6,0,0],"v":[0,6,0],"material":"g"}],)"
    R"("spheres":[{"center":[-1.2,1,0],"radius":0.8,"material":"y"},)"
    R"({"center":[-1.2,1,0],"radius":0.8,"material":"c"}],)"
    R"("disks":[{"center":[1.2,-1,0],"normal":[0,0,1],"radius":0.8,"material":"m"},)"
    R"({"center":[1.2,-1,0],"normal":[0,0,1],"radius":0.8,"material":"b"}]})";

// Pixels of each color in an 8-bit image.
std::map<std::array<std::uint8_t, 3>, int> color_counts(const image_rgb8& image) {
  std::map<std::array<std::uint8_t, 3>, int> counts;
  for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3)
    ++counts[{image.rgb[p], image.rgb[p + 1], image.rgb[p + 2]}];
  return counts;
}

TEST(FastMode, CoincidentSurfacesShowTheLaterObject) {
  const scene s = parse_scene_json(coincident_json, "coincident.json");
  const image_rgb8 fast = render_with(s, cpu_precision::fast);
  EXPECT_EQ(fast.rgb, render_with(s, cpu_precision::reference).rgb);
  const auto counts = color_counts(fast);
  const auto count = [&](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const auto it = counts.find({r, g, b});
    return it == counts.end() ? 0 : it->second;
  };
  EXPECT_EQ(count(255, 0, 0) + count(255, 255, 0) + count(255, 0, 255), 0);  // the earlier
  EXPECT_GT(count(0, 255, 0), 3000);   // the later quad, around the others
  EXPECT_GT(count(0, 255, 255), 300);  // the later sphere
  EXPECT_GT(count(0, 0, 255), 300);    // the later disk
}

// Asked to stop, the fast mode stops as the reference does: render_cancelled, no image.
TEST(FastMode, ACancelledRenderStops) {
  scene s = load_scene("book-final", {});
  s.render.width = 64;
  engine_options e;
  e.precision = cpu_precision::fast;
  e.cancelled = [] { return true; };
  EXPECT_THROW(render_cpu(test::scene_camera(s), s, s.render, {}, e), render_cancelled);
}

// --precision: auto draws the built-in scenes with the reference (the books' images, byte for
// byte) and files with the fast mode; the summary says which; a wrong word is refused with exit 2.
TEST(FastMode, TheCliPicksTheReferenceForBuiltInScenesAndTheFastModeForFiles) {
  test::temp_dir dir;
  const std::string out = (dir.path() / "x.ppm").string();
  const std::string file =
      (fs::path(RTVK_TEST_DATA) / ".." / ".." / "docs" / "scenes" / "disks.json").string();
  const auto builtin = test::run_rtvk({"render", "seed", "--width", "32", "-o", out});
  ASSERT_EQ(builtin.status, 0) << builtin.err;
  EXPECT_NE(builtin.err.find("on cpu in"), std::string::npos) << builtin.err;
  const auto from_file = test::run_rtvk({"render", file, "--width", "32", "--spp", "1", "-o", out});
  ASSERT_EQ(from_file.status, 0) << from_file.err;
  EXPECT_NE(from_file.err.find("on cpu (fast) in"), std::string::npos) << from_file.err;
  const auto forced =
      test::run_rtvk({"render", "seed", "--width", "32", "--precision", "fast", "-o", out});
  EXPECT_NE(forced.err.find("on cpu (fast) in"), std::string::npos) << forced.err;
  fs::remove(out);
  const auto wrong = test::run_rtvk({"render", "seed", "--precision", "double", "-o", out});
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("--precision"), std::string::npos) << wrong.err;
  EXPECT_NE(wrong.err.find("double"), std::string::npos) << wrong.err;
  EXPECT_FALSE(fs::exists(out));
}

// rtvk bench --precision both times each mode in the same run, and its records say which.
TEST(FastMode, BenchTimesBothModesInOneRun) {
  test::temp_dir dir;
  const std::string json = (dir.path() / "b.json").string();
  const auto r = test::run_rtvk({"bench", "--scene", "cornell-box", "--backend", "cpu", "--width",
                                 "32", "--spp", "2", "--precision", "both", "--json", json});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = test::slurp(json);
  EXPECT_NE(text.find("\"precision\": \"fast\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"precision\": \"reference\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"accel\": \"embree\""), std::string::npos) << text;
  EXPECT_NE(r.out.find("embree, fast"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bvh, reference"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rtvk
