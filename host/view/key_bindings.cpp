#include "key_bindings.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "camera_controls.h"

namespace rtvk::view {

// The keys that move the camera: each is one pure function of the pose (camera_controls.h).
camera_pose moved_by_key(const camera_pose& p, int key) {
  switch (key) {
    case GLFW_KEY_W:
      return fly(p, 1, 0, 0);
    case GLFW_KEY_S:
      return fly(p, -1, 0, 0);
    case GLFW_KEY_D:
      return fly(p, 0, 1, 0);
    case GLFW_KEY_A:
      return fly(p, 0, -1, 0);
    case GLFW_KEY_E:
      return fly(p, 0, 0, 1);
    case GLFW_KEY_Q:
      return fly(p, 0, 0, -1);
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      return zoom(p, 1);
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      return zoom(p, -1);
    case GLFW_KEY_RIGHT_BRACKET:
      return stop(p, 1);
    case GLFW_KEY_LEFT_BRACKET:
      return stop(p, -1);
    case GLFW_KEY_P:
      return next_projection(p);
    default:
      return p;
  }
}

}  // namespace rtvk::view
