#include "overlay_shader.h"

// The generated header declares a uint32_t array without including <cstdint> itself.
#include <cstdint>

#include "overlay_spv.h"

namespace rtvk::view {

std::span<const std::uint32_t> overlay_shader() {
  return overlay_spv;
}

}  // namespace rtvk::view
