// The GPU tests run on Mesa's lavapipe unless RTVK_TEST_DEVICE names another device: the
// harness selects the driver itself, so a machine's real GPU does not change what CI checks.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "gpu_fixture.h"

int main(int argc, char** argv) {
  // rtvk keeps compiled pipelines in the user's cache folder: the tests, and the rtvk they run,
  // use a folder of their own, removed at the end.
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("rtvk-test-cache-" + std::to_string(getpid()));
  setenv("XDG_CACHE_HOME", cache.c_str(), 1);
  if (rtvk::test::test_device().empty()) {
    setenv("VK_DRIVER_FILES", rtvk::test::lavapipe_icd, 1);
    setenv("VK_ICD_FILENAMES", rtvk::test::lavapipe_icd, 1);  // loaders older than 1.3.207
  }
  testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  std::error_code ec;
  std::filesystem::remove_all(cache, ec);
  return status;
}
