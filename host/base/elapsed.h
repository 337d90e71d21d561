#pragma once
#include <chrono>

namespace rtvk {

// Wall-clock seconds since `start` (a steady clock: never jumps with the system time).
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rtvk
