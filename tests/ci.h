#pragma once
#include <cstdlib>
#include <string>

namespace rtvk::test {

// True under CI (CI set and not "false" or "0"): there, a test that cannot check what it is
// about fails instead of skipping.
inline bool in_ci() {
  const char* ci = std::getenv("CI");
  return ci && *ci && std::string(ci) != "false" && std::string(ci) != "0";
}

}  // namespace rtvk::test
