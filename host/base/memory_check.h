#pragma once
#include <cstdint>

namespace rtvk {

// Bytes of memory the system can still hand out (MemAvailable), or 0 when unknown.
std::uint64_t available_memory_bytes();

}  // namespace rtvk
