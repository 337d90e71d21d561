#pragma once
#include <stdexcept>

namespace rtvk {

// Bad input from the user (a flag, a value, a file they named): the CLI exits 2.
// Every other exception is a failure while running: the CLI exits 1.
class usage_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A render stopped early because it was asked to (engine_options::cancelled); says how far it
// got. The CLI exits 128 + the signal that asked.
class render_cancelled : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rtvk
