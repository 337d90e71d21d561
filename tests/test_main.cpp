// The GPU tests run on Mesa's lavapipe unless RTVK_TEST_DEVICE names another device: the
// harness selects the driver itself, so a machine's real GPU does not change what CI checks.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gpu_fixture.h"

int main(int argc, char** argv) {
  if (rtvk::test::test_device().empty()) {
    setenv("VK_DRIVER_FILES", rtvk::test::lavapipe_icd, 1);
    setenv("VK_ICD_FILENAMES", rtvk::test::lavapipe_icd, 1);  // loaders older than 1.3.207
  }
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
