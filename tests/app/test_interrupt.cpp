// Interruption and device faults, on the real executable: a stopped render exits 128 + signal,
// says how far it got, and leaves no file; a hung device becomes an error, not a hang.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "fault_layer.h"
#include "gpu_fixture.h"
#include "process.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;

// Long enough on any machine that the signal arrives mid-render (seconds on this project's).
std::vector<std::string> long_render(const fs::path& out, const std::string& backend) {
  return {"render",    "--scene", "book-final", "--spp", "200",
          "--backend", backend,   "--validate", "-o",    out.string()};
}

void expect_interrupted(const std::string& backend, int sig, int status, const char* name) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.png";
  test::running_rtvk p(long_render(out, backend));
  ASSERT_TRUE(p.wait_until_catching(sig, std::chrono::seconds(30)));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // well into the render
  p.signal(sig);
  const auto r = p.wait();
  EXPECT_EQ(r.status, status) << r.err;
  EXPECT_NE(r.err.find(std::string("interrupted by ") + name + ": stopped after"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("was not written"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("validation:"), std::string::npos) << "clean shutdown: " << r.err;
  EXPECT_TRUE(fs::is_empty(dir.path())) << "no file, not even a temporary one";
}

TEST(Interrupt, SigintStopsACpuRender) {
  expect_interrupted("cpu", SIGINT, 130, "SIGINT");
}
TEST(Interrupt, SigtermStopsACpuRender) {
  expect_interrupted("cpu", SIGTERM, 143, "SIGTERM");
}

// Whether `dir`'s file system offers O_TMPFILE (overlayfs before Linux 6.6, ZFS and NFS do not).
bool offers_o_tmpfile(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY, 0600);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// SIGKILL cannot be caught: what it leaves is what the file system holds at that moment. The
// test pause holds rtvk after the image's bytes are written and flushed but before they get
// their name, the worst moment; the kill lands there. With O_TMPFILE nothing has a name yet;
// where the file system lacks it, rtvk's fallback has a named temporary file there (the one
// case where one can be left), and the output path is still never partial.
void expect_killed_mid_write_leaves_nothing(bool target_exists) {
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.ppm";
  if (target_exists) std::ofstream(out) << "the old image";
  const std::vector<std::string> before = files_in(dir.path());
  test::running_rtvk p({"render", "--scene", "seed", "--width", "2000", "-q", "-o", out.string()},
                       {"RTVK_TEST_PAUSE_BEFORE_COMMIT=60"});
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (p.stderr_so_far().find("written, not yet committed") == std::string::npos &&
         std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_NE(p.stderr_so_far().find("written, not yet committed"), std::string::npos)
      << p.stderr_so_far();
  const std::vector<std::string> paused = files_in(dir.path());
  p.signal(SIGKILL);
  EXPECT_EQ(p.wait().status, 128 + SIGKILL);
  if (offers_o_tmpfile(dir.path())) {
    EXPECT_EQ(paused, before) << "nothing named while the data waits";
    EXPECT_EQ(files_in(dir.path()), before) << "no file and no temporary file";
  } else {
    EXPECT_EQ(paused.size(), before.size() + 1) << "the fallback's named temporary file";
  }
  if (target_exists) {
    EXPECT_EQ(test::slurp(out), "the old image");
  } else {
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(Interrupt, SigkillDuringTheWriteLeavesNoFileAndNoTemporaryFile) {
  expect_killed_mid_write_leaves_nothing(false);
}

TEST(Interrupt, SigkillDuringTheWriteOverAnImageLeavesTheOldImageAlone) {
  expect_killed_mid_write_leaves_nothing(true);
}

class GpuInterrupt : public test::GpuTest {};

TEST_F(GpuInterrupt, SigintStopsAGpuRenderAndReleasesTheDeviceCleanly) {
  if (!test::test_device().empty()) GTEST_SKIP() << "uses lavapipe's speed for its timing";
  expect_interrupted("gpu", SIGINT, 130, "SIGINT");
}

// A device lost part way (the test layer answers VK_ERROR_DEVICE_LOST from the third submission
// on): exit 1 naming the call and the device, no image, no crash while the engine is torn down.
TEST_F(GpuInterrupt, ALostDeviceIsAnErrorAndWritesNoImage) {
  test::temp_dir dir;
  for (const char* out_name : {"out.png", "out.exr"}) {
    const fs::path out = dir.path() / out_name;
    std::vector<std::string> args{"render", "--scene", "book-final", "--width",
                                  "300",    "--spp",   "20",         "--backend",
                                  "gpu",    "-o",      out.string()};
    if (!test::test_device().empty()) args.insert(args.end(), {"--device", test::test_device()});
    const auto r = test::run_rtvk(args, test::fault_environment("lose-device-at-submit:3"));
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("vkQueueSubmit: VK_ERROR_DEVICE_LOST (device " + gpu().device().name),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out)) << out_name;
  }
}

TEST_F(GpuInterrupt, AHungDeviceIsAnErrorNotAHang) {
  // A fence timeout far shorter than the work stands in for a hung device.
  test::temp_dir dir;
  const fs::path out = dir.path() / "out.png";
  std::vector<std::string> args{"render", "--scene", "book-final", "--width", "600",
                                "--spp",  "20",      "--backend",  "gpu",     "--gpu-timeout",
                                "0.001",  "-o",      out.string()};
  if (!test::test_device().empty()) args.insert(args.end(), {"--device", test::test_device()});
  const auto r = test::run_rtvk(args);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("vkWaitForFences: VK_TIMEOUT"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(gpu().device().name), std::string::npos) << "names the device: " << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace rtvk
