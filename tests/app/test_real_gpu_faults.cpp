// What a desktop GPU does and lavapipe does not, played by the test layer (tests/view/layers) on
// the real executable: a watchdog that loses the device when one submission runs too long
// (Windows' TDR, Linux's GPU job timeouts), a small maxComputeWorkGroupCount enforced, a
// discrete GPU's memory (device-local memory the host cannot map, host memory the shaders should
// not read) and VK_EXT_memory_budget's budget.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fault_layer.h"
#include "gpu_fixture.h"
#include "process.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class RealGpuFaults : public test::GpuTest {};

// book-final with --accel none tests all 485 spheres for every ray: one sample over the whole
// 1200x800 image took one 7.7-second submission on lavapipe before dispatches were bounded, and
// the watchdog lost the device. Now every dispatch's pixels times its loop budget is bounded
// before anything is measured, submissions are paced to at most a second on lavapipe, and the
// render finishes under the watchdog with the image a render without it (and with the BVH)
// gives. The watchdog allows 4 s, not Windows' 2: another test may share the machine's cores.
TEST_F(RealGpuFaults, ALongRenderFinishesUnderAWatchdogWithTheSameImage) {
  test::temp_dir dir;
  const fs::path plain = dir.path() / "plain.png", guarded = dir.path() / "guarded.png";
  const std::vector<std::string> common{"render", "--scene", "book-final", "--backend",
                                        "gpu",    "--spp",   "1"};
  auto args = common;
  args.insert(args.end(), {"-o", plain.string()});
  const auto want = run_rtvk(args);
  ASSERT_EQ(want.status, 0) << want.err;

  args = common;
  args.insert(args.end(), {"--accel", "none", "-o", guarded.string()});
  const auto got = run_rtvk(args, test::fault_environment("watchdog:4000"));
  ASSERT_EQ(got.status, 0) << got.err;
  EXPECT_EQ(got.err.find("watchdog"), std::string::npos) << got.err;
  EXPECT_TRUE(bytes_of(plain) == bytes_of(guarded)) << "the image changed";
}

// The watchdog is real: a render's submissions take longer than a millisecond, the device is
// lost, and rtvk says so (exit 1, the call and its VkResult) and writes nothing.
TEST_F(RealGpuFaults, TheWatchdogLosesTheDevice) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "lost.png";
  const auto r = run_rtvk({"render", "--scene", "book-final", "--backend", "gpu", "--width", "200",
                           "--spp", "4", "-o", out.string()},
                          test::fault_environment("watchdog:1"));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("VK_ERROR_DEVICE_LOST"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// A device whose maxComputeWorkGroupCount is 3 in every dimension (the layer loses the device on
// any dispatch past it): the render's bands, its views (an animation's frames are the dispatch's
// z) and the device's 8-bit encoding are all tiled within it, and give the unlimited device's
// bytes.
TEST_F(RealGpuFaults, DispatchesStayWithinTheWorkgroupCountLimit) {
  test::temp_dir dir;
  for (const bool animated : {false, true}) {
    SCOPED_TRACE(animated ? "an animation" : "one image");
    std::vector<std::string> args{"render",  "--scene", "book-final", "--backend", "gpu",
                                  "--width", "120",     "--spp",      "3"};
    if (animated) args.insert(args.end(), {"--frames", "0:5"});
    const fs::path a = dir.path() / (animated ? "a-{frame}.png" : "a.png");
    const fs::path b = dir.path() / (animated ? "b-{frame}.png" : "b.png");
    auto plain = args;
    plain.insert(plain.end(), {"-o", a.string()});
    const auto want = run_rtvk(plain);
    ASSERT_EQ(want.status, 0) << want.err;
    auto limited = args;
    limited.insert(limited.end(), {"-o", b.string()});
    const auto got = run_rtvk(limited, test::fault_environment("workgroup-count:3"));
    ASSERT_EQ(got.status, 0) << got.err;
    for (const auto& entry : fs::directory_iterator(dir.path())) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("a", 0) != 0) continue;
      EXPECT_TRUE(bytes_of(entry.path()) == bytes_of(dir.path() / ("b" + name.substr(1)))) << name;
    }
  }
}

// A discrete GPU's memory types (the layer's discrete-memory: device-local memory the host
// cannot map, host-visible memory in a heap of its own): the scene goes through upload copies,
// every buffer a shader reads or writes (sums, status counters, camera block, thresholds, scene)
// is device-local (the layer loses the device when one is bound from host memory: before, the
// status block and the thresholds were), and the image, read back through host memory, is the
// one lavapipe's own memory gives (where the scene is written in place). A render to bytes, one
// to linear sums (EXR) and an animation's frames.
TEST_F(RealGpuFaults, OnADiscreteGpusMemoryShadersReadOnlyDeviceLocalBuffers) {
  test::temp_dir dir;
  for (const char* kind : {"png", "exr", "frames"}) {
    SCOPED_TRACE(kind);
    const std::string ext = kind == std::string("exr") ? ".exr" : ".png";
    const std::string name = kind == std::string("frames") ? "-{frame}" : "";
    std::vector<std::string> args{"render",  "--scene", "book-final", "--backend", "gpu",
                                  "--width", "100",     "--spp",      "3"};
    if (kind == std::string("frames")) args.insert(args.end(), {"--frames", "0:3"});
    const fs::path a = dir.path() / (std::string("a") + kind + name + ext);
    const fs::path b = dir.path() / (std::string("b") + kind + name + ext);
    auto plain = args;
    plain.insert(plain.end(), {"-o", a.string()});
    const auto want = run_rtvk(plain);
    ASSERT_EQ(want.status, 0) << want.err;
    auto discrete = args;
    discrete.insert(discrete.end(), {"-o", b.string()});
    const auto got = run_rtvk(discrete, test::fault_environment("discrete-memory"));
    ASSERT_EQ(got.status, 0) << got.err;
    EXPECT_EQ(got.err.find("rtvk test layer"), std::string::npos) << got.err;
    const auto file = [&](const fs::path& pattern, int frame) {
      std::string s = pattern.string();
      const auto at = s.find("{frame}");
      if (at != std::string::npos) s.replace(at, 7, std::to_string(frame));
      return fs::path(s);
    };
    for (int f = 0; f < (kind == std::string("frames") ? 3 : 1); ++f)
      EXPECT_TRUE(bytes_of(file(a, f)) == bytes_of(file(b, f)) && !bytes_of(file(a, f)).empty())
          << "frame " << f;
  }
}

// A device that reports VK_EXT_memory_budget (the layer adds it) with less to spare than the
// render needs: refused before anything is allocated, exit 2, naming the heap, the need and the
// budget, no file. With room, the same render goes through.
TEST_F(RealGpuFaults, ARenderPastTheMemoryBudgetIsRefusedWithExit2) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "budget.png";
  const std::vector<std::string> args{"render", "--scene", "book-final", "--backend",
                                      "gpu",    "--width", "120",        "--spp",
                                      "2",      "-o",      out.string()};
  const auto refused = run_rtvk(args, test::fault_environment("memory-budget:100"));
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("--scene book-final: the render needs "), std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("has 100 KiB of it to spare (VK_EXT_memory_budget)"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(out));
  const auto fits = run_rtvk(args, test::fault_environment("memory-budget:100000"));
  EXPECT_EQ(fits.status, 0) << fits.err;
  EXPECT_TRUE(fs::exists(out));
}

}  // namespace
}  // namespace rtvk
