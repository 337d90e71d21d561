// The CPU's fast mode against the GPU: the same kernels in the same float, over the same arrays,
// drawing the same numbers. Only the searches differ (Embree's triangle tests, its quads inside
// instanced groups, and which of two objects an exact tie goes to there; the world's own spheres,
// quads and disks are the kernels' tests and the GPU's ties), and what the compilers make of the
// arithmetic.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "gpu_fixture.h"
#include "render_helpers.h"
#include "scene_file.h"

namespace rtvk {
namespace {

class GpuFastMode : public test::GpuTest {};

// What each built-in scene measured on lavapipe at 80 pixels wide and 8 samples (PSNR, pixels
// more than 2 levels off); 1e9: the same bytes.
const std::map<std::string, std::pair<double, int>> gpu_measured = {
    {"seed", {1e9, 0}},
    {"materials", {1e9, 0}},
    {"book-final", {1e9, 0}},
    {"bouncing-spheres", {85.5, 0}},
    {"quads", {1e9, 0}},
    {"checkered-spheres", {1e9, 0}},
    {"perlin-spheres", {1e9, 0}},
    {"simple-light", {1e9, 0}},
    {"cornell-box", {1e9, 0}},
    {"cornell-smoke", {1e9, 0}},
    {"next-week-final", {80.2, 0}},
    {"rest-of-life-final", {1e9, 0}},
    {"showcase", {84.2, 0}},
};

TEST_F(GpuFastMode, EveryBuiltInSceneMatchesTheGpu) {
  engine_options fast;
  fast.precision = cpu_precision::fast;
  for (const std::string& name : scene_names()) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(gpu_measured.count(name)) << "a new built-in scene: measure it here";
    scene s = load_scene(name, {});
    s.render.width = 80;
    s.render.spp = std::min(s.render.spp, 8);
    const camera cam = test::scene_camera(s);
    const image_rgb8 cpu = quantize(render_cpu(cam, s, s.render, {}, fast), s.render.encoding());
    const image_difference d =
        compare_images(test::gpu_image(gpu(), s, cam), cpu, monte_carlo_agreement.tolerance);
    const auto [psnr, over] = gpu_measured.at(name);
    const int pixels = cpu.width * cpu.height;
    const agreement rule = test::measured_agreement(psnr, double(over) / pixels, pixels);
    std::printf("%s: %.1f dB, %ld pixels over 2 levels\n", name.c_str(), d.psnr_db,
                long(d.pixels_over));
    EXPECT_GE(d.psnr_db, rule.min_psnr_db);
    EXPECT_LE(d.share_over, rule.max_share) << d.pixels_over << " pixels";
  }
}

// Exact ties (coincident surfaces, test_fast_mode.cpp's scene): the fast mode draws the GPU's
// bytes, the later object's colors.
TEST_F(GpuFastMode, CoincidentSurfacesMatchTheGpu) {
  const scene s = parse_scene_json(
      R"({"camera":{"lookfrom":[0,0,6],"lookat":[0,0,0],"vfov":60},)"
      R"("render":{"gamma":1,"width":48,"aspect":"1:1","spp":1,"jitter":false,"max_depth":2},)"
      R"("materials":{"r":{"type":"flat","albedo":[1,0,0]},"g":{"type":"flat","albedo":[0,1,0]},)"
      R"("y":{"type":"flat","albedo":[1,1,0]},"c":{"type":"flat","albedo":[0,1,1]}},)"
      R"("quads":[{"Q":[-3,-3,-1],"u":[6,0,0],"v":[0,6,0],"material":"r"},)"
      R"({"Q":[-3,-3,-1],"u":[6,0,0],"v":[0,6,0],"material":"g"}],)"
      R"("spheres":[{"center":[-1.2,1,0],"radius":0.8,"material":"y"},)"
      R"({"center":[-1.2,1,0],"radius":0.8,"material":"c"}]})",
      "coincident.json");
  engine_options fast;
  fast.precision = cpu_precision::fast;
  const camera cam = test::scene_camera(s);
  const image_rgb8 cpu = quantize(render_cpu(cam, s, s.render, {}, fast), s.render.encoding());
  EXPECT_EQ(test::gpu_image(gpu(), s, cam).rgb, cpu.rgb);
}

}  // namespace
}  // namespace rtvk
