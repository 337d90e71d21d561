// Color management at the command line (docs/color.md): the defaults of scene files, mesh files
// and the built-in scenes, known sRGB bytes, exposure as twice the light per stop, texture color
// spaces, the scene file's fields round trip, and bad values refused naming the flag or field.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "image_io.h"
#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

void color_write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// A 4x4 render whose every pixel is the background: the one sphere is behind the camera.
std::string color_sky_scene(const std::string& render, const std::string& background) {
  return R"({"render":{"width":4,"aspect":1,"spp":1,"max_depth":2)" + render +
         R"(},"camera":{"lookfrom":[0,0,0],"lookat":[0,0,-1]},"background":)" + background +
         R"(,"materials":{"m":{"type":"flat","albedo":[1,1,1]}},)"
         R"("spheres":[{"center":[0,0,5],"radius":1,"material":"m"}]})";
}

// The first pixel of a rendered PNG.
std::array<int, 3> color_pixel(const fs::path& png) {
  const image_rgb8 img = read_image(png);
  return {img.rgb[0], img.rgb[1], img.rgb[2]};
}

std::array<int, 3> color_render(const test::temp_dir& dir, const std::string& scene_text,
                                std::vector<std::string> flags = {}) {
  const fs::path scene = dir.path() / "sky.json", out = dir.path() / "sky.png";
  color_write(scene, scene_text);
  std::vector<std::string> args{"render", "-q", "--scene", scene.string(), "-o", out.string()};
  args.insert(args.end(), flags.begin(), flags.end());
  const auto r = run_rtvk(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return color_pixel(out);
}

TEST(CliColor, NewSceneFilesAreSrgbAndFilesThatSetGammaKeepThePowerLaw) {
  test::temp_dir dir;
  const std::string sky = "[0.5, 0.18, 0.0031308]";
  // sRGB: 0.5 -> 0.7354 -> 188, 0.18 -> 0.4614 -> 118, 0.0031308 -> 12.92 * it = 0.0404 -> 10.
  EXPECT_EQ(color_render(dir, color_sky_scene("", sky)), (std::array<int, 3>{188, 118, 10}));
  // "gamma": 1 as before: int(255.999 c).
  EXPECT_EQ(color_render(dir, color_sky_scene(R"(,"gamma":1)", sky)),
            (std::array<int, 3>{127, 46, 0}));
  EXPECT_EQ(color_render(dir, color_sky_scene(R"(,"gamma":2)", sky)),
            (std::array<int, 3>{181, 108, 14}));  // sqrt: 0.7071, 0.4243, 0.0560
  // The field and the flag choose.
  EXPECT_EQ(color_render(dir, color_sky_scene(R"(,"gamma":2,"view_transform":"standard")", sky)),
            (std::array<int, 3>{188, 118, 10}));
  EXPECT_EQ(color_render(dir, color_sky_scene("", sky), {"--view-transform", "linear"}),
            (std::array<int, 3>{127, 46, 0}));
  // AgX keeps mid grey where sRGB has it.
  EXPECT_EQ(
      color_render(dir, color_sky_scene("", "[0.18, 0.18, 0.18]"), {"--view-transform", "agx"}),
      (std::array<int, 3>{118, 118, 118}));
}

TEST(CliColor, OneStopOfExposureIsTwiceTheLightUnderEveryTransform) {
  test::temp_dir dir;
  for (const char* t : {"standard", "filmic", "agx", "linear", "gamma"}) {
    SCOPED_TRACE(t);
    const auto doubled =
        color_render(dir, color_sky_scene("", "[0.6, 0.2, 1.4]"), {"--view-transform", t});
    EXPECT_EQ(color_render(dir, color_sky_scene("", "[0.3, 0.1, 0.7]"),
                           {"--view-transform", t, "--exposure", "1"}),
              doubled);
    EXPECT_EQ(color_render(dir, color_sky_scene(R"(,"exposure":1)", "[0.3, 0.1, 0.7]"),
                           {"--view-transform", t}),
              doubled);
  }
}

TEST(CliColor, BadTransformsAndExposuresExitTwoNamingTheFlagOrField) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "x.png";
  const auto flag = run_rtvk({"render", "--view-transform", "filmix", "-o", out.string()});
  EXPECT_EQ(flag.status, 2);
  EXPECT_NE(
      flag.err.find("--view-transform filmix: expected standard, filmic, agx, linear or gamma"),
      std::string::npos)
      << flag.err;
  const auto ev = run_rtvk({"render", "--exposure", "17", "-o", out.string()});
  EXPECT_EQ(ev.status, 2);
  EXPECT_NE(ev.err.find("--exposure"), std::string::npos) << ev.err;
  const fs::path scene = dir.path() / "bad.json";
  color_write(scene, color_sky_scene(R"(,"view_transform":"aces")", "[0,0,0]"));
  const auto field = run_rtvk({"render", "--scene", scene.string(), "-o", out.string()});
  EXPECT_EQ(field.status, 2);
  EXPECT_EQ(std::count(field.err.begin(), field.err.end(), '\n'), 1) << field.err;
  EXPECT_NE(field.err.find("/render/view_transform: expected standard, filmic, agx, linear or "
                           "gamma, got \"aces\""),
            std::string::npos)
      << field.err;
  color_write(scene, color_sky_scene(R"(,"exposure":-40)", "[0,0,0]"));
  const auto far = run_rtvk({"render", "--scene", scene.string(), "-o", out.string()});
  EXPECT_EQ(far.status, 2);
  EXPECT_NE(far.err.find("/render/exposure"), std::string::npos) << far.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliColor, DumpsKeepTheTransformAndMeshFilesAreSrgb) {
  test::temp_dir dir;
  const fs::path scene = dir.path() / "s.json", obj = dir.path() / "t.obj";
  color_write(scene, color_sky_scene(R"(,"view_transform":"agx","exposure":-1.5)", "[0,0,0]"));
  const auto dumped = run_rtvk({"scene", "dump", scene.string()});
  ASSERT_EQ(dumped.status, 0) << dumped.err;
  EXPECT_NE(dumped.out.find("\"view_transform\": \"agx\""), std::string::npos) << dumped.out;
  EXPECT_NE(dumped.out.find("\"exposure\": -1.5"), std::string::npos) << dumped.out;
  const auto book = run_rtvk({"scene", "dump", "book-final"});
  EXPECT_NE(book.out.find("\"view_transform\": \"gamma\""), std::string::npos);
  color_write(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto mesh = run_rtvk({"scene", "dump", obj.string()});
  ASSERT_EQ(mesh.status, 0) << mesh.err;
  EXPECT_NE(mesh.out.find("\"view_transform\": \"standard\""), std::string::npos) << mesh.out;
  // And a picture, not the lesson's one sample: jittered, 32 samples, 16 bounces.
  EXPECT_NE(mesh.out.find("\"spp\": 32"), std::string::npos) << mesh.out;
  EXPECT_NE(mesh.out.find("\"jitter\": true"), std::string::npos) << mesh.out;
  EXPECT_NE(mesh.out.find("\"max_depth\": 16"), std::string::npos) << mesh.out;
  EXPECT_NE(mesh.out.find("\"sky\": {\"horizon\":[0.3,0.3,0.3],\"zenith\":[0.7,0.7,0.7]}"),
            std::string::npos)
      << mesh.out;
}

TEST(CliColor, ImageTexturesDecodeByTheirColorSpace) {
  test::temp_dir dir;
  write_image(image_rgb8{1, 1, {128, 128, 128}}, dir.path() / "grey.png");
  const auto textured = [&](const std::string& space) {
    return R"({"render":{"width":4,"aspect":1,"spp":1,"max_depth":2,"view_transform":"linear"},)"
           R"("camera":{"lookfrom":[0,0,0],"lookat":[0,0,-1],"vfov":10},)"
           R"("materials":{"m":{"type":"flat","albedo":{"type":"image","file":"grey.png")" +
           space + R"(}}},"spheres":[{"center":[0,0,-3],"radius":1,"material":"m"}]})";
  };
  // Byte 128 -> linear, then the book's floor(256 v) byte, shown linear: 128/255 = 0.502 -> 128;
  // sRGB's inverse 0.2158 -> 55; the book's (128/255)^2.2 = 0.2195 -> 56.
  EXPECT_EQ(color_render(dir, textured(R"(,"color_space":"linear")"))[0], 128);
  EXPECT_EQ(color_render(dir, textured(R"(,"color_space":"srgb")"))[0], 55);
  EXPECT_EQ(color_render(dir, textured(""))[0], 56);
  EXPECT_EQ(color_render(dir, textured(R"(,"color_space":"book")"))[0], 56);
  const fs::path scene = dir.path() / "bad.json";
  color_write(scene, textured(R"(,"color_space":"rec709")"));
  const auto r =
      run_rtvk({"render", "--scene", scene.string(), "-o", (dir.path() / "y.png").string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/materials/m/albedo/color_space: expected \"book\", \"srgb\" or "
                       "\"linear\", got \"rec709\""),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace rtvk
