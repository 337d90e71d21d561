#pragma once
// The environment that loads the test layer of tests/view/layers into rtvk with one fault: the
// device cannot present ("no-present"), is lost ("lose-device-at-submit:N",
// "lose-device-after-present:N"), loses itself when one submission runs longer than a watchdog
// allows ("watchdog:MS"), or says it is an NVIDIA GPU ("disguise-device"), has a discrete GPU's
// memory ("discrete-memory"), a memory budget ("memory-budget:KIB") or a compute-only queue
// family ("compute-queue-family"); the layer's source lists every fault.
#include <cstdio>
#include <string>
#include <vector>

namespace rtvk::test {

inline std::vector<std::string> fault_environment(const std::string& fault) {
  return {"VK_ADD_LAYER_PATH=" RTVK_TEST_LAYER_DIR, "VK_INSTANCE_LAYERS=VK_LAYER_RTVK_test_faults",
          "RTVK_TEST_FAULT=" + fault};
}

// Under "compute-queue-family": the submissions the layer counted (printed at vkDestroyDevice)
// to compute-only families (the layer's, and a real GPU's own) and to the others; {-1, -1} when
// it printed none.
struct queue_submissions {
  long compute_only = -1;
  long others = -1;
};
inline queue_submissions submissions_per_queue(const std::string& err) {
  const std::string line = "rtvk test layer: submissions: ";
  const std::size_t at = err.find(line);
  queue_submissions q;
  if (at == std::string::npos ||
      std::sscanf(err.c_str() + at + line.size(), "%ld to compute-only families, %ld",
                  &q.compute_only, &q.others) != 2)
    return {};
  return q;
}

}  // namespace rtvk::test
