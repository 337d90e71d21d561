#include "render_memory.h"

#include <algorithm>
#include <string>

#include "errors.h"
#include "format.h"
#include "memory_check.h"
#include "render_gpu.h"

namespace rtvk {

std::uint64_t render_memory_bytes(int width, int height, int renders) {
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  return pixels * (24 + 3 + 12) * std::uint64_t(renders) + gpu::default_band_bytes;
}

void check_render_memory(int width, int height, int renders) {
  const std::uint64_t need = render_memory_bytes(width, height, renders);
  const memory_room room = available_memory();
  if (room.bytes == 0 || need <= room.bytes) return;
  throw usage_error(std::to_string(width) + "x" + std::to_string(height) + " needs about " +
                    format_bytes(need) + " of memory; " + format_bytes(room.bytes) +
                    " is available (" + room.limit + "): lower --width or use a smaller --aspect");
}

std::size_t gpu_group_size(int width, int height) {
  const std::uint64_t per_view = std::uint64_t(width) * std::uint64_t(height) * 24;
  return std::size_t(std::clamp<std::uint64_t>((256ull << 20) / per_view, 1, RTVK_MAX_VIEWS));
}

}  // namespace rtvk
