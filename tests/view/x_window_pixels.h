#pragma once
#include <string>

#include "image_rgb8.h"

namespace rtvk::test {

// What the X server shows in window `id` (decimal, as xdotool prints it) on `display`, as 8-bit
// RGB rows from the top; an empty image when it cannot be read. Xlib lives in its own file: its
// macros (None, Status, Bool) would collide with the tests'.
image_rgb8 window_pixels(const std::string& display, const std::string& id);

}  // namespace rtvk::test
