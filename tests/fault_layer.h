#pragma once
// The environment that loads the test layer of tests/view/layers into rtvk with one fault: the
// device cannot present ("no-present"), is lost ("lose-device-at-submit:N",
// "lose-device-after-present:N"), loses itself when one submission runs longer than a watchdog
// allows ("watchdog:MS"), or says it is an NVIDIA GPU ("disguise-device"), has a discrete GPU's
// memory ("discrete-memory") or a memory budget ("memory-budget:KIB"); the layer's source lists
// every fault.
#include <string>
#include <vector>

namespace rtvk::test {

inline std::vector<std::string> fault_environment(const std::string& fault) {
  return {"VK_ADD_LAYER_PATH=" RTVK_TEST_LAYER_DIR, "VK_INSTANCE_LAYERS=VK_LAYER_RTVK_test_faults",
          "RTVK_TEST_FAULT=" + fault};
}

}  // namespace rtvk::test
