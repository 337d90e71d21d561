// Tests of the real rtvk executable: exit codes, messages, and the files it leaves behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <tuple>

#include "lesson_reference.h"
#include "process.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

int count_lines(const std::string& s) {
  return int(std::count(s.begin(), s.end(), '\n'));
}

TEST(Cli, HelpAndVersion) {
  const auto help = run_rtvk({"--help"});
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("render"), std::string::npos);
  const auto render_help = run_rtvk({"render", "--help"});
  EXPECT_EQ(render_help.status, 0);
  EXPECT_NE(render_help.out.find("--width"), std::string::npos);
  const auto version = run_rtvk({"--version"});
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("rtvk ", 0), 0u) << version.out;
}

TEST(Cli, NoSubcommandIsUsageError) {
  EXPECT_EQ(run_rtvk({}).status, 2);
}

TEST(Cli, RenderWritesTheLessonsImage) {
  test::temp_dir dir;
  for (auto [aspect_flag, aspect, width] :
       {std::tuple{"16:9", 16.0 / 9.0, 400}, {"2", 2.0, 333}, {"4:3", 4.0 / 3.0, 97}}) {
    const fs::path out = dir.path() / "seed.ppm";
    const auto r = run_rtvk({"render", "--scene", "seed", "--backend", "cpu", "--aspect",
                             aspect_flag, "--width", std::to_string(width), "-o", out.string()});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;  // the one summary line
    EXPECT_NE(r.err.find("cpu"), std::string::npos) << r.err;
    // Compared as a whole: on a difference GoogleTest's line diff of two 100,000-line files would
    // take more memory than a CI machine has.
    EXPECT_TRUE(test::slurp(out) == lesson::render_seed_p3(aspect, width)) << aspect_flag;
  }
}

// What a new user types first: the scene as the argument, without --scene. The same image as
// --scene gives, and a second scene is refused.
TEST(Cli, TheSceneMayBeGivenWithoutItsFlag) {
  test::temp_dir dir;
  const fs::path a = dir.path() / "a.ppm", b = dir.path() / "b.ppm";
  const auto r = run_rtvk({"render", "materials", "--width", "48", "-o", a.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(run_rtvk({"render", "--scene", "materials", "--width", "48", "-o", b.string()}).status,
            0);
  EXPECT_EQ(test::slurp(a), test::slurp(b));
  EXPECT_NE(test::slurp(a), lesson::render_seed_p3(16.0 / 9.0, 48));  // not the default scene
  const auto twice =
      run_rtvk({"render", "materials", "seed", "-o", (dir.path() / "c.ppm").string()});
  EXPECT_EQ(twice.status, 2);
  EXPECT_FALSE(fs::exists(dir.path() / "c.ppm"));
}

TEST(Cli, PngAndP6Outputs) {
  test::temp_dir dir;
  EXPECT_EQ(run_rtvk({"render", "-q", "-o", (dir.path() / "a.png").string()}).status, 0);
  EXPECT_EQ(test::slurp(dir.path() / "a.png").substr(1, 3), "PNG");
  EXPECT_EQ(run_rtvk({"render", "-q", "--ppm-format", "p6", "-o", (dir.path() / "b.ppm").string()})
                .status,
            0);
  EXPECT_EQ(test::slurp(dir.path() / "b.ppm").substr(0, 2), "P6");
}

struct bad_input {
  std::vector<std::string> args;  // flags after "render", before -o
  std::string flag;               // must be named in the message
  std::string value;              // must be named in the message
};

TEST(Cli, BadInputExits2WithAMessageAndNoFile) {
  const std::vector<bad_input> cases = {
      {{"--width", "0"}, "--width", "0"},
      {{"--width", "-5"}, "--width", "-5"},
      {{"--width", "abc"}, "--width", "abc"},
      {{"--width", "65537"}, "--width", "65537"},
      {{"--aspect", "0"}, "--aspect", "0"},
      {{"--aspect", "-1.5"}, "--aspect", "-1.5"},
      {{"--aspect", "nan"}, "--aspect", "nan"},
      {{"--aspect", "inf"}, "--aspect", "inf"},
      {{"--aspect", "16:0"}, "--aspect", "16:0"},
      {{"--aspect", "a:b"}, "--aspect", "a:b"},
      {{"--aspect", "0.000001"}, "--aspect", "0.000001"},
      {{"--scene", "nope"}, "--scene", "nope"},
      {{"--backend", "quantum"}, "--backend", "quantum"},
      {{"--projection", "fisheye"}, "--projection", "fisheye"},
      {{"--fisheye-fov", "400"}, "--fisheye-fov", "400"},
      {{"--fisheye-fov", "0"}, "--fisheye-fov", "0"},
      {{"--projection", "equirectangular", "--aperture", "0.5"}, "aperture", "0.5"},
      {{"--shutter", "1:0"}, "--shutter", "1:0"},
      {{"--shutter", "abc"}, "--shutter", "abc"},
      {{"--shutter", "0:inf"}, "--shutter", "0:inf"},
      {{"--shutter", "0:1x"}, "--shutter", "0:1x"},
  };
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.png";
  for (const auto& c : cases) {
    std::vector<std::string> args{"render"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.insert(args.end(), {"-o", out.string()});
    const auto r = run_rtvk(args);
    const std::string where = c.args[0] + " " + c.args[1];
    EXPECT_EQ(r.status, 2) << where << ": " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << where << ": " << r.err;
    EXPECT_NE(r.err.find(c.flag), std::string::npos) << where << ": " << r.err;
    EXPECT_NE(r.err.find(c.value), std::string::npos) << where << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << where;
    EXPECT_TRUE(fs::is_empty(dir.path())) << where;
  }
}

TEST(Cli, BadOutputPathExits2) {
  test::temp_dir dir;
  for (const fs::path& out :
       {dir.path() / "x.jpg", dir.path() / "missing" / "x.png", dir.path() / "noext"}) {
    const auto r = run_rtvk({"render", "-o", out.string()});
    EXPECT_EQ(r.status, 2) << out << ": " << r.err;
    EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  EXPECT_EQ(run_rtvk({"render"}).status, 2);  // no -o at all
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace rtvk
