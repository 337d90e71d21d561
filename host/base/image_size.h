#pragma once

namespace rtvk {

// The largest image side rtvk accepts, in pixels.
inline constexpr int max_image_side = 65536;

}  // namespace rtvk
