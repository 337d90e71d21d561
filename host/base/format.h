#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

namespace rtvk {

// Shortest readable form of a number for messages: 1.77778, 1e-09, inf, nan.
inline std::string format_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// A size in the largest binary unit that keeps the number at 1 or more: "244.141 MiB", "1 GiB",
// "100 KiB", "16 bytes".
inline std::string format_bytes(std::uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double value = double(bytes);
  int unit = 0;
  while (value >= 1024 && unit < 4) {
    value /= 1024;
    ++unit;
  }
  return format_number(value) + " " + units[unit];
}

}  // namespace rtvk
