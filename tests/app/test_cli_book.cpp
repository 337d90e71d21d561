// The real executable with the book's features: flags, scene files, progress.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include "ci.h"
#include "image_io.h"
#include "process.h"
#include "sanitizers.h"

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
      {"--lookat", "nan,0,0"}, {"--scene", "nope.json"}, {"--sampling", "importance"},
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

// Lights sampling asked of a scene without lights: refused naming the flag, nothing written. The
// summary says which sampling ran, and bench's records carry it and the dropped samples.
TEST(CliBook, SamplingIsNamedRefusedWithoutLightsAndReported) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.png";
  const auto refused = run_rtvk({"render", "--sampling", "lights", "-o", out.string()});
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("--sampling lights: the scene has no lights to aim at"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(out));
  const auto lit = run_rtvk({"render", "--scene", "cornell-box", "--width", "32", "--spp", "4",
                             "--backend", "cpu", "-o", out.string()});
  ASSERT_EQ(lit.status, 0) << lit.err;
  EXPECT_NE(lit.err.find("4 spp (lights sampling), on cpu"), std::string::npos) << lit.err;
  const auto plain = run_rtvk({"render", "--scene", "cornell-box", "--width", "32", "--spp", "4",
                               "--sampling", "plain", "--backend", "cpu", "-o", out.string()});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.err.find("4 spp, on cpu"), std::string::npos) << plain.err;
  const std::string json = (dir.path() / "b.json").string();
  const auto bench = run_rtvk({"bench", "--scene", "cornell-box", "--width", "16", "--spp", "2",
                               "--backend", "cpu", "--json", json});
  ASSERT_EQ(bench.status, 0) << bench.err;
  EXPECT_NE(bench.out.find(", lights sampling:"), std::string::npos) << bench.out;
  const std::string records = test::slurp(json);
  EXPECT_NE(records.find("\"sampling\": \"lights\""), std::string::npos) << records;
  EXPECT_NE(records.find("\"dropped_samples\": 0"), std::string::npos) << records;
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
  EXPECT_EQ(
      run_rtvk({"scene", "list"}).out,
      "seed\nmaterials\nbook-final\nbouncing-spheres\nquads\ncheckered-spheres\nperlin-spheres\n"
      "simple-light\ncornell-box\ncornell-smoke\nnext-week-final\nrest-of-life-final\nshowcase\n"
      "spheres:N (N "
      "from 1 to "
      "4000000)\n");
}

// A shutter open past time 1 (the spheres go on rising): bench bounds them over it on both
// backends, as render does (it once refused: its BVH covered [0, 1] only).
TEST(CliBench, AShutterPastTimeOneIsBenchedOnBothBackends) {
  const auto r = run_rtvk({"bench", "--scene", "bouncing-spheres", "--shutter", "0:2", "--width",
                           "64", "--spp", "2", "--backend", "all"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cpu  bouncing-spheres 64x36"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("gpu  bouncing-spheres 64x36"), std::string::npos) << r.out;
}

// Frames of an animation sample instants past time 1, where the bouncing spheres go on rising
// (linear beyond center1): the BVH bounds them over every frame's shutter, so each frame is the
// image of a search without it, byte for byte, and the GPU renders them too.
TEST(CliBook, AnAnimationOfMovingSpheresBoundsThemOverEveryFrame) {
  test::temp_dir dir;
  const std::vector<std::string> flags{"--scene", "bouncing-spheres", "--width", "80",    "--spp",
                                       "2",       "--frames",         "0:3",     "--fps", "1",
                                       "-q"};
  const auto render = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args{"render", "-o", (dir.path() / name).string()};
    args.insert(args.end(), flags.begin(), flags.end());
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_rtvk(args);
    EXPECT_EQ(r.status, 0) << r.err;
  };
  render("bvh-{frame}.png", {"--backend", "cpu"});
  render("none-{frame}.png", {"--backend", "cpu", "--accel", "none"});
  render("gpu-{frame}.png", {"--backend", "gpu"});
  for (int f = 0; f < 3; ++f) {
    const std::string n = std::to_string(f) + ".png";
    EXPECT_EQ(test::slurp((dir.path() / ("bvh-" + n)).string()),
              test::slurp((dir.path() / ("none-" + n)).string()))
        << "frame " << f;
    EXPECT_TRUE(fs::exists(dir.path() / ("gpu-" + n))) << "frame " << f;
  }
  EXPECT_NE(test::slurp((dir.path() / "bvh-0.png").string()),
            test::slurp((dir.path() / "bvh-2.png").string()))
      << "the spheres moved";
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

// What rtvk writes to stderr when stderr is a terminal: a pseudo-terminal this test opens.
// Empty optional when this system offers no pseudo-terminals (no /dev/pts).
std::optional<std::string> stderr_on_a_terminal(const std::vector<std::string>& args) {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
    if (master >= 0) ::close(master);
    return std::nullopt;
  }
  const std::string slave = ::ptsname(master);
  test::running_rtvk p(args, {"RTVK_PROGRESS_DELAY=0"}, slave);
  std::string seen;
  char buf[4096];
  for (;;) {  // read until the child has exited and closed its end (read then fails with EIO)
    const ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break;
    seen.append(buf, std::size_t(n));
  }
  p.wait();
  ::close(master);
  return seen;
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

  const auto tty = stderr_on_a_terminal(args);
  if (!tty) {
    if (test::in_ci()) FAIL() << "no pseudo-terminals (/dev/pts) in CI: the bar cannot be checked";
    GTEST_SKIP()
        << "this system has no pseudo-terminals (/dev/pts): the bar's drawing is not checked";
  }
  EXPECT_NE(tty->find("rendering on the CPU ["), std::string::npos) << *tty;
  EXPECT_NE(tty->find("% "), std::string::npos) << *tty;
  EXPECT_NE(tty->find("left"), std::string::npos) << *tty;
  std::vector<std::string> quiet = args;
  quiet.push_back("--quiet");
  EXPECT_EQ(stderr_on_a_terminal(quiet)->find("rendering on the CPU ["), std::string::npos);
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

namespace rtvk {
namespace {

// Runs rtvk with args under `ulimit -v` of `kib` KiB (the shell sets it, then becomes rtvk).
// AddressSanitizer reserves terabytes of address space for its shadow memory at start, so an
// rtvk built with it cannot start under any such limit: the tests that use this are not built
// with it (the ci pass runs them; a skip would show in the asan pass of CI).
#if !RTVK_ASAN
test::process_result run_rtvk_under_ulimit(long kib, std::vector<std::string> args) {
  args.insert(args.begin(),
              {"-c", "ulimit -v " + std::to_string(kib) + " && exec \"$0\" \"$@\"", RTVK_EXE});
  return test::running_rtvk(args, {}, "", "/bin/sh").wait();
}

TEST(CliBook, ImageTooLargeForMemoryIsRefusedUpFront) {
  test::temp_dir dir;
  const auto out = (dir.path() / "huge.ppm").string();
  // 65536 x 65536 needs over 150 GiB: refused before any work, naming what it needs. An H200
  // machine had that much available, and this test then rendered for two minutes: the process's
  // address space is limited to 4 GiB here, so the answer is the same on every machine.
  const auto r =
      run_rtvk_under_ulimit(4 << 20, {"render", "--width", "65536", "--aspect", "1", "-o", out});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("65536x65536 needs about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("GiB"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A Slurm job's --mem, a pod's memory limit and `ulimit -v` bound what rtvk may use, not the
// machine's free memory: a render that fits the machine but not the limit is refused with exit
// 2 naming the limit (before, it was started and then killed, or failed an allocation).
TEST(CliBook, TheRenderFitsUnderTheProcesssMemoryLimit) {
  test::temp_dir dir;
  const auto out = (dir.path() / "big.ppm").string();
  const auto r =
      run_rtvk_under_ulimit(1 << 20, {"render", "--width", "8192", "--aspect", "1", "-o", out});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("8192x8192 needs about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(ulimit -v)"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

#endif  // !RTVK_ASAN

// libstb's PNG encoder overflows its int-sized buffers past about 1 GiB of rows: a 65536x65536
// PNG crashed rtvk with SIGSEGV after rendering for two minutes. Refused up front now, on every
// machine (the PNG check comes before the memory check), naming the flag and the way out.
TEST(CliBook, APngLargerThanTheEncoderTakesIsRefusedBeforeRendering) {
  test::temp_dir dir;
  const auto out = (dir.path() / "huge.png").string();
  const auto r = run_rtvk({"render", "--width", "65536", "--aspect", "2", "-o", out});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--output: '" + out + "': a 65536x32768 PNG has 6.00"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("write .exr or .ppm"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

// Every bad scene file, through the real executable: exit 2, one line naming the file and what
// is wrong, nothing rendered.
TEST(CliBadInput, SceneFiles) {
  const std::string m = R"("materials":{"m":{"type":"normal"}})";
  const struct {
    std::string name, content, expect;
  } cases[] = {
      {"empty.json", "", "empty scene file"},
      {"not_json.json", "this is not JSON", "parse error at line 1, column "},
      {"wrong_shape.json", "[1, 2, 3]", "/: expected an object"},
      {"wrong_type.json", "{" + m + R"(,"spheres":[{"center":"here","radius":1,"material":"m"}]})",
       "/spheres/0/center: expected an array of 3 numbers"},
      {"negative_radius.json",
       "{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":-1,"material":"m"}]})",
       "/spheres/0/radius: expected a radius > 0, got -1"},
      {"zero_radius.json",
       "{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":0,"material":"m"}]})",
       "/spheres/0/radius: expected a radius > 0, got 0"},
      {"infinite.json",
       "{" + m + R"(,"spheres":[{"center":[0,1e400,0],"radius":1,"material":"m"}]})",
       "number overflow"},
      {"unknown_material.json", R"({"materials":{"m":{"type":"unobtainium"}},"spheres":[]})",
       "/materials/m/type: unknown material type \"unobtainium\""},
      {"missing_material.json",
       "{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1,"material":"x"}]})",
       "/spheres/0/material: no material named \"x\""},
  };
  test::temp_dir dir;
  const auto out = (dir.path() / "out.png").string();
  for (const auto& c : cases) {
    const auto file = (dir.path() / c.name).string();
    std::ofstream(file) << c.content;
    const auto r = run_rtvk({"render", "--scene", file, "-o", out});
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(file + ": "), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.name << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
  }
  // Missing, and unreadable (a folder stands in: root reads any file whatever its mode).
  for (const std::string& path :
       {(dir.path() / "missing.json").string(), dir.path().string() + "/"}) {
    const auto r = run_rtvk({"render", "--scene", path, "-o", out});
    EXPECT_EQ(r.status, 2) << path << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(CliBadInput, AHundredThousandSphereFileRenders) {
  test::temp_dir dir;
  const auto file = (dir.path() / "big.json").string();
  {
    // Rows of 317 spheres across x = -158..158, one row per unit of depth from z = -20 back.
    std::ofstream f(file);
    f << R"({"render":{"gamma":1},"materials":{"m":{"type":"normal"}},"spheres":[)";
    for (int i = 0; i < 100000; ++i)
      f << (i ? "," : "") << R"({"center":[)" << (i % 317 - 158) << ",0," << (-20 - i / 317)
        << R"(],"radius":0.4,"material":"m"})";
    f << "]}";
  }
  const auto out = (dir.path() / "big.png").string();
  const auto r =
      run_rtvk({"render", "--scene", file, "--width", "65", "--aspect", "1.94", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  // 65 / 1.94 = 33.5, so 65x33, and pixel (32, 16) looks through (u, v) = (32/64, 16/32) =
  // (0.5, 0.5): straight down -z onto the sphere at (0, 0, -20), head on, normal (0, 0, 1),
  // shaded 0.5 * (normal + 1) = (0.5, 0.5, 1) and written int(255.999 * c) = 127, 127, 255.
  const image_rgb8 img = read_image(out);
  ASSERT_EQ(img.width, 65);
  ASSERT_EQ(img.height, 33);
  const std::uint8_t* center = img.pixel(32, 16);
  EXPECT_EQ(std::vector<int>(center, center + 3), (std::vector<int>{127, 127, 255}));
}

TEST(CliBadInput, UnwritableOutputFolder) {
  // /proc accepts no new files, even from root; the check runs before any rendering.
  const auto r = run_rtvk({"render", "-o", "/proc/rtvk-test.png"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--output: cannot write in folder '/proc'"), std::string::npos) << r.err;
  if (::geteuid() != 0) {  // and a folder without write permission, where that means something
    test::temp_dir dir;
    std::filesystem::permissions(
        dir.path(), std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const auto r2 = run_rtvk({"render", "-o", (dir.path() / "x.png").string()});
    EXPECT_EQ(r2.status, 2) << r2.err;
    std::filesystem::permissions(dir.path(), std::filesystem::perms::owner_all);
  }
}

}  // namespace
}  // namespace rtvk
