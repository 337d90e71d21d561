#pragma once
#include <functional>
#include <stdexcept>
#include <string>

namespace rtvk {

// While one of these lives, SIGINT and SIGTERM do not kill the process: they are recorded, and a
// render polls `interrupt_requested` and stops at its next pass. A second signal ends the process
// at once. The previous handlers are restored on destruction.
class interrupt_guard {
 public:
  interrupt_guard();
  ~interrupt_guard();
  interrupt_guard(const interrupt_guard&) = delete;
  interrupt_guard& operator=(const interrupt_guard&) = delete;
};

// The signal received (SIGINT, SIGTERM), or 0.
int pending_signal();

// The cancellation poll renderers take: true once a signal has arrived.
inline std::function<bool()> interrupt_requested() {
  return [] { return pending_signal() != 0; };
}

}  // namespace rtvk
