// What a desktop GPU does and lavapipe does not, played by the test layer (tests/view/layers) on
// the real executable: a watchdog that loses the device when one submission runs too long
// (Windows' TDR, Linux's GPU job timeouts), and a small maxComputeWorkGroupCount enforced.
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

}  // namespace
}  // namespace rtvk
