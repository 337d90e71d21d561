#include "interrupt.h"

#include <csignal>

namespace rtvk {
namespace {

volatile std::sig_atomic_t received = 0;  // the signal number, 0 before any
struct sigaction previous_int, previous_term;

extern "C" void on_signal(int sig) {
  if (received != 0) {  // asked twice: stop now, the default way
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  received = sig;
}

}  // namespace

interrupt_guard::interrupt_guard() {
  received = 0;
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
  return received;
}

}  // namespace rtvk
