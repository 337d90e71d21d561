// The GPU tests run on the software rasterizer the suite finds by its driver ID (lavapipe,
// whatever its manifest is called and wherever it is installed) unless RTVK_TEST_DEVICE names
// another device; every rtvk the tests run gets the same device through RTVK_DEVICE
// (tests/process.h), so a machine's real GPU does not change what CI checks. The device is
// looked for when a test first needs it, not in tests that need none.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "software_device.h"

namespace {

// `rtvk_tests --pick-software-device`: the suite's device pick alone, for the test that runs it
// against a loader set up otherwise (tests/gpu/test_device_pick.cpp). Prints the index and the
// device on stdout and exits 0, or the failure on stderr and exits 1.
int print_pick() {
  const rtvk::test::device_pick pick = rtvk::test::find_software_device();
  if (!pick.found) {
    std::fprintf(stderr, "%s\n", pick.failure.c_str());
    return 1;
  }
  std::printf("%u\n%s\n", pick.index, pick.description.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--pick-software-device") return print_pick();
  // rtvk keeps compiled pipelines in the user's cache folder: the tests, and the rtvk they run,
  // use a folder of their own, removed at the end.
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("rtvk-test-cache-" + std::to_string(getpid()));
  setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  // Mesa keeps the machine code it compiles from rtvk's shaders in its own cache, under
  // XDG_CACHE_HOME unless MESA_SHADER_CACHE_DIR says where: with the folder above, every test
  // process would compile every shader variant it uses again, and Mesa 25's lavapipe takes up to
  // a minute for the largest (GpuSampling.LightsSamplingMatchesTheCpu: 116 s cold, 4 s warm).
  // The suite's processes, and the rtvk they run, share one Mesa cache in the build tree instead
  // (scripts/test.sh points every pass at one): it holds only the driver's compiled code, keyed
  // by the SPIR-V and the driver's build, so what a test checks is made anew by each test.
  setenv("MESA_SHADER_CACHE_DIR", RTVK_TEST_MESA_CACHE, 0);
  testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  std::error_code ec;
  std::filesystem::remove_all(cache, ec);
  return status;
}
