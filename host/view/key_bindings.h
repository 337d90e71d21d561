#pragma once
#include "camera.h"

namespace rtvk::view {

// The pose after key `key` (a GLFW key code) moved it: fly, zoom, stop, projection
// (docs/viewer.md); other keys leave it as it was.
camera_pose moved_by_key(const camera_pose& p, int key);

}  // namespace rtvk::view
