#pragma once
#include <cstdio>
#include <string>

namespace rtvk {

// Shortest readable form of a number for messages: 1.77778, 1e-09, inf, nan.
inline std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace rtvk
