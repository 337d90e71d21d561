#include "memory_check.h"

#include <fstream>
#include <sstream>
#include <string>

#include "errors.h"
#include "format.h"

namespace rtvk {

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

std::uint64_t render_memory_bytes(int width, int height, int renders) {
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  return pixels * (24 + 3 + 4) * std::uint64_t(renders) + (64u << 20);
}

void check_render_memory(int width, int height, int renders) {
  const std::uint64_t need = render_memory_bytes(width, height, renders);
  const std::uint64_t have = available_memory_bytes();
  if (have == 0 || need <= have) return;
  throw usage_error(std::to_string(width) + "x" + std::to_string(height) + " needs about " +
                    format_bytes(need) + " of memory; " + format_bytes(have) +
                    " is available (lower --width or use a smaller --aspect)");
}

}  // namespace rtvk
