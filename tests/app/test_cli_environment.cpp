// rtvk render with environment maps (issue 46): --environment and a scene file's "environment"
// render, and bad maps exit 2 with one line naming the flag or field, writing nothing.
#include <gtest/gtest.h>

#include <ImfRgbaFile.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "environment_scenes.h"
#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

using test::run_rtvk;

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A 4x2 OpenEXR map of one color, (value, value / 2, value / 4).
void write_exr(const std::filesystem::path& path, float value) {
  std::vector<Imf::Rgba> px(8, Imf::Rgba(value, value / 2, value / 4, 1));
  Imf::RgbaOutputFile f(path.c_str(), 4, 2, Imf::WRITE_RGB);
  f.setFrameBuffer(px.data(), 1, 4);
  f.writePixels(2);
}

// An OpenEXR map's R, G and B channels are its radiance (values RGBE holds exactly).
TEST(CliEnvironment, AnExrMapIsReadAsItsChannels) {
  test::temp_dir dir;
  write_exr(dir.path() / "m.exr", 2.0f);
  environment_map e;
  e.image = load_environment_image(dir.path() / "m.exr", "test");
  ASSERT_EQ(e.image->width, 4);
  ASSERT_EQ(e.image->height, 2);
  const environment_tables t(e);
  EXPECT_EQ(environment_radiance(t.view(), vec3(0.3, -0.5, 0.8)), color(2.0, 1.0, 0.5));
}

TEST(CliEnvironment, TheFlagAndTheSceneFieldRenderTheSameImage) {
  test::temp_dir dir;
  const std::string hdr = (dir.path() / "sky-sun.hdr").string();
  write_file(hdr, file_bytes(test::sky_sun_file));
  const std::string scene = (dir.path() / "s.json").string();
  write_file(scene, R"({"camera": {"lookfrom": [0, 1, 4], "lookat": [0, 0.5, 0]},
    "render": {"width": 32, "aspect": 1, "spp": 2},
    "environment": {"file": "sky-sun.hdr", "strength": 0.5},
    "materials": {"white": {"type": "lambertian", "albedo": [0.8, 0.8, 0.8]}},
    "spheres": [{"center": [0, 0.5, 0], "radius": 0.5, "material": "white"}]})");
  const std::string a = (dir.path() / "a.ppm").string(), b = (dir.path() / "b.ppm").string();
  const auto ra = run_rtvk({"render", "--scene", scene, "-q", "-o", a});
  ASSERT_EQ(ra.status, 0) << ra.err;
  const auto rb =
      run_rtvk({"render", "--scene", scene, "--environment", hdr + ":0.5", "-q", "-o", b});
  ASSERT_EQ(rb.status, 0) << rb.err;
  EXPECT_EQ(file_bytes(a), file_bytes(b));
  // Strength 1 is brighter: the flag's strength is used (without one, the scene's is kept).
  const std::string c = (dir.path() / "c.ppm").string();
  ASSERT_EQ(
      run_rtvk({"render", "--scene", scene, "--environment", hdr + ":1", "-q", "-o", c}).status, 0);
  EXPECT_NE(file_bytes(a), file_bytes(c));
}

TEST(CliEnvironment, BadMapsExit2NamingTheFlagOrFieldAndWriteNothing) {
  test::temp_dir dir;
  const std::string good = file_bytes(test::sky_sun_file);
  write_file(dir.path() / "cut.hdr", good.substr(0, good.size() / 2));
  write_file(dir.path() / "big.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4096 +X 8192\n");
  write_exr(dir.path() / "nan.exr", std::nanf(""));
  write_exr(dir.path() / "negative.exr", -1.0f);
  write_file(dir.path() / "sky.hdr", good);
  const auto at = [&](const char* name) { return (dir.path() / name).string(); };
  write_file(dir.path() / "strength.json",
             R"({"environment": {"file": "sky.hdr", "strength": -1},
                 "spheres": [{"center": [0, 0, -1], "radius": 0.5}]})");
  write_file(dir.path() / "missing.json",
             R"({"environment": {"file": "none.hdr"},
                 "spheres": [{"center": [0, 0, -1], "radius": 0.5}]})");
  struct bad {
    std::vector<std::string> args;  // after render -q -o OUT
    std::string says;               // in the message
  };
  const std::vector<bad> cases = {
      {{"--scene", "seed", "--environment", at("none.hdr")}, "--environment"},
      {{"--scene", "seed", "--environment", at("cut.hdr")}, "truncated"},
      {{"--scene", "seed", "--environment", at("big.hdr")}, "8192x4096 texels is past the limit"},
      {{"--scene", "seed", "--environment", at("nan.exr")}, "texel 0,0 is nan"},
      {{"--scene", "seed", "--environment", at("negative.exr")}, "texel 0,0 is -1"},
      {{"--scene", "seed", "--environment", at("sky.hdr") + ":-1"}, "the strength must be"},
      {{"--scene", at("strength.json")}, "/environment/strength"},
      {{"--scene", at("missing.json")}, "/environment/file"},
  };
  for (const bad& b : cases) {
    const std::string out = at("out.png");
    std::vector<std::string> args = {"render", "-q", "-o", out};
    args.insert(args.end(), b.args.begin(), b.args.end());
    const auto r = run_rtvk(args);
    EXPECT_EQ(r.status, 2) << b.says << ": " << r.err;
    EXPECT_NE(r.err.find(b.says), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << b.says;
  }
}

}  // namespace
}  // namespace rtvk
