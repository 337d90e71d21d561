// --aov through the real executable: the files and channels it writes beside the image, the
// lesson's sphere at its known distance, the device's AOVs checked against the CPU's, and bad
// lists refused before anything is written.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

std::set<std::string> channels_of(const fs::path& file) {
  Imf::InputFile in(file.c_str());
  std::set<std::string> out;
  for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c)
    out.insert(c.name());
  return out;
}

// One channel of an OpenEXR file, as floats (UINT channels converted by OpenEXR).
std::vector<float> channel(const fs::path& file, const char* name, int& width) {
  Imf::InputFile in(file.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  width = dw.max.x - dw.min.x + 1;
  const int height = dw.max.y - dw.min.y + 1;
  std::vector<float> v(std::size_t(width) * std::size_t(height));
  Imf::FrameBuffer fb;
  fb.insert(name, Imf::Slice::Make(Imf::FLOAT, v.data(), dw, sizeof(float),
                                   std::size_t(width) * sizeof(float)));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  return v;
}

// The lesson's scene, 65 pixels square: the center pixel's ray goes straight down -z and meets
// the small sphere (center (0, 0, -1), radius 0.5) at distance 0.5; the bottom row sees the
// ground sphere.
TEST(CliAov, APngRendersAovsLandBesideItWithTheLessonsDistances) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "lesson.png";
  const auto r = run_rtvk({"render", "--width", "65", "--aspect", "1", "--aov",
                           "depth,object-id,material-id", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(dir.path() / "lesson.normal.exr"));
  EXPECT_EQ(channels_of(dir.path() / "lesson.depth.exr"), (std::set<std::string>{"distance", "Z"}));
  int w = 0;
  const std::vector<float> distance = channel(dir.path() / "lesson.depth.exr", "distance", w);
  const std::vector<float> z = channel(dir.path() / "lesson.depth.exr", "Z", w);
  const std::vector<float> id = channel(dir.path() / "lesson.object-id.exr", "object_id", w);
  const std::vector<float> mat = channel(dir.path() / "lesson.material-id.exr", "material_id", w);
  ASSERT_EQ(w, 65);
  const std::size_t center = 32 * 65 + 32, bottom = 64 * 65 + 32, top = 32;
  EXPECT_NEAR(distance[center], 0.5, 1e-6);
  EXPECT_NEAR(z[center], 0.5, 1e-6);
  EXPECT_EQ(id[center], 1);  // the first sphere
  EXPECT_EQ(id[bottom], 2);  // the ground
  EXPECT_EQ(id[top], 0);     // the sky: nothing
  EXPECT_TRUE(std::isinf(distance[top]));
  EXPECT_EQ(mat[center], 1);  // material 0, counted from 1
}

TEST(CliAov, AnExrRenderCarriesTheAovsAsChannelsAndTheDeviceAgrees) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "box.exr";
  const auto r =
      run_rtvk({"render", "--scene", "cornell-box", "--width", "48", "--spp", "2", "--backend",
                "both", "--aov", "depth,normal,albedo,object-id,material-id", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("gpu vs cpu AOVs: alike"), std::string::npos) << r.err;
  EXPECT_EQ(channels_of(out),
            (std::set<std::string>{"R", "G", "B", "distance", "Z", "N.X", "N.Y", "N.Z", "albedo.R",
                                   "albedo.G", "albedo.B", "object_id", "material_id"}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()), 1);
}

TEST(CliAov, BadListsExit2NamingTheFlagAndWriteNothing) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "x.png";
  for (const std::string bad : {"bogus", "depth,", "depth,,normal", ",", "Depth"}) {
    const auto r = run_rtvk({"render", "--aov", bad, "-o", out.string()});
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("--aov " + bad + ":"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(dir.path())) << bad;
  }
}

}  // namespace
}  // namespace rtvk
