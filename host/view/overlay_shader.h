#pragma once
#include <cstdint>
#include <span>

namespace rtvk::view {

// overlay.comp's SPIR-V, compiled at build time and embedded in this library: the viewer is its
// only user.
std::span<const std::uint32_t> overlay_shader();

}  // namespace rtvk::view
