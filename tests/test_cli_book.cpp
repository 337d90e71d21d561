// The real executable with the book's features: flags, scene files, progress.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "process.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

TEST(CliBook, BadFlagsExit2NamingFlagAndValue) {
  const std::vector<std::vector<std::string>> cases = {
      {"--spp", "0"},          {"--spp", "-3"},          {"--depth", "-1"},
      {"--depth", "0"},        {"--seed", "-1"},         {"--vfov", "180"},
      {"--vfov", "0"},         {"--aperture", "-1"},     {"--focus-dist", "0"},
      {"--lookfrom", "1,2"},   {"--lookfrom", "a,b,c"},  {"--vup", "1,2,3,4"},
      {"--lookat", "nan,0,0"}, {"--scene", "nope.json"},
  };
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.png";
  for (const auto& c : cases) {
    std::vector<std::string> args{"render"};
    args.insert(args.end(), c.begin(), c.end());
    args.insert(args.end(), {"-o", out.string()});
    const auto r = run_rtvk(args);
    EXPECT_EQ(r.status, 2) << c[0] << " " << c[1] << ": " << r.err;
    EXPECT_NE(r.err.find(c[0] == "--scene" ? "nope.json" : c[0]), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c[1]), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // The camera cannot look at where it stands.
  const auto r =
      run_rtvk({"render", "--lookfrom", "1,1,1", "--lookat", "1,1,1", "-o", out.string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("lookfrom and lookat"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(CliBook, DumpedSceneRendersTheIdenticalImage) {
  test::temp_dir dir;
  const auto json = (dir.path() / "materials.json").string();
  const auto dump = run_rtvk({"scene", "dump", "materials"});
  ASSERT_EQ(dump.status, 0) << dump.err;
  std::ofstream(json) << dump.out;
  const auto a = (dir.path() / "a.ppm").string(), b = (dir.path() / "b.ppm").string();
  const std::vector<std::string> flags{"--width", "64", "--spp", "3", "-q"};
  std::vector<std::string> builtin{"render", "--scene", "materials", "-o", a};
  std::vector<std::string> file{"render", "--scene", json, "-o", b};
  builtin.insert(builtin.end(), flags.begin(), flags.end());
  file.insert(file.end(), flags.begin(), flags.end());
  ASSERT_EQ(run_rtvk(builtin).status, 0);
  ASSERT_EQ(run_rtvk(file).status, 0);
  EXPECT_EQ(test::slurp(a), test::slurp(b));
  EXPECT_EQ(run_rtvk({"scene", "list"}).out,
            "seed\nmaterials\nbook-final\nspheres:N (N from 1 to 4000000)\n");
}

TEST(CliBook, BadSceneFileExits2WithFileAndPath) {
  test::temp_dir dir;
  const auto json = (dir.path() / "bad.json").string();
  std::ofstream(json)
      << R"({"materials":{"m":{"type":"normal"}},"spheres":[{"center":[0,0,-1],"radius":-2,"material":"m"}]})";
  const auto out = dir.path() / "x.png";
  const auto r = run_rtvk({"render", "--scene", json, "-o", out.string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(json + ": /spheres/0/radius"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliBook, SeedAndOverridesChangeTheImageDeterministically) {
  test::temp_dir dir;
  auto render = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args{
        "render", "--scene", "materials", "--width", "48",
        "--spp",  "2",       "-q",        "-o",      (dir.path() / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    EXPECT_EQ(run_rtvk(args).status, 0);
    return test::slurp(dir.path() / name);
  };
  const std::string a = render("a.ppm", {}), again = render("b.ppm", {});
  EXPECT_EQ(a, again);  // same seed, same image
  EXPECT_NE(render("c.ppm", {"--seed", "7"}), a);
  EXPECT_NE(render("d.ppm", {"--lookfrom", "-2,2,1", "--vfov", "40", "--aperture", "0"}), a);
}

TEST(CliBook, ProgressBarOnlyOnATerminal) {
  test::temp_dir dir;
  const auto out = (dir.path() / "p.png").string();
  // The bar normally waits a second before it appears; RTVK_PROGRESS_DELAY=0 draws it at once,
  // so the test does not depend on how fast this machine renders.
  const std::vector<std::string> args{"render", "--scene", "book-final", "--width", "160",
                                      "--spp",  "4",       "-o",         out};
  const auto plain = run_rtvk(args, {"RTVK_PROGRESS_DELAY=0"});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.err.find('\r'), std::string::npos) << "progress noise in a log: " << plain.err;
  // Under a pseudo-terminal (script from util-linux), the bar is drawn...
  auto under_tty = [&](const std::string& extra) {
    std::string cmd = "RTVK_PROGRESS_DELAY=0 script -qec '" + std::string(RTVK_EXE);
    for (const auto& a : args) cmd += " " + a;
    cmd += extra + "' /dev/null > " + (dir.path() / "tty.txt").string() + " 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    return test::slurp(dir.path() / "tty.txt");
  };
  const std::string tty = under_tty("");
  EXPECT_NE(tty.find("rendering on the CPU ["), std::string::npos) << tty;
  EXPECT_NE(tty.find("% "), std::string::npos) << tty;
  EXPECT_NE(tty.find("left"), std::string::npos) << tty;
  // ...unless --quiet.
  EXPECT_EQ(under_tty(" --quiet").find("rendering on the CPU ["), std::string::npos);
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

TEST(CliBench, ReportsRaysAndWritesJsonRecords) {
  test::temp_dir dir;
  const auto json = (dir.path() / "bench.json").string();
  const auto r = run_rtvk({"bench", "--scene", "seed", "--backend", "cpu", "--width", "32",
                           "--repeat", "2", "--threads", "1", "--json", json});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
  const std::string text = test::slurp(json);
  // The seed scene traces exactly one ray per pixel: 32 x 18.
  EXPECT_NE(text.find("\"rays\": 576"), std::string::npos) << text;
  for (const char* field : {"\"scene\": \"seed\"", "\"backend\": \"cpu\"", "\"device\"",
                            "\"threads\": 1", "\"width\": 32", "\"height\": 18", "\"spp\": 1",
                            "\"depth\": 50", "\"seconds\"", "\"mrays_per_s\""})
    EXPECT_NE(text.find(field), std::string::npos) << field << "\n" << text;
  // Two timed runs, two records.
  std::size_t records = 0;
  for (std::size_t at = 0; (at = text.find("\"scene\"", at)) != std::string::npos; ++at) ++records;
  EXPECT_EQ(records, 2u);
}

TEST(CliBench, SpheresSceneNamesAreChecked) {
  for (const char* bad : {"spheres:0", "spheres:abc", "spheres:", "spheres:99999999"}) {
    const auto r = run_rtvk({"bench", "--scene", bad, "--backend", "cpu"});
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace rtvk
