#include "interrupt.h"

#include <atomic>
#include <csignal>

namespace rtvk {
namespace {

// The signal number, 0 before any. Stored by the handler and read by every render thread, so it
// is an atomic (a volatile sig_atomic_t is safe for the handler but a data race between threads),
// and a lock-free one, as a handler may only touch those.
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);
struct sigaction previous_int, previous_term;

extern "C" void on_signal(int sig) {
  if (received.load() != 0) {  // asked twice: stop now, the default way
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  received.store(sig);
}

}  // namespace

interrupt_guard::interrupt_guard() {
  received.store(0);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

interrupt_guard::~interrupt_guard() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int pending_signal() {
  return received.load(std::memory_order_relaxed);
}

}  // namespace rtvk
