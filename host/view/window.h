#pragma once
#include <string>
#include <vector>

#include <volk.h>

struct GLFWwindow;

namespace rtvk::view {

// GLFW, initialized for the life of this object. Throws usage_error when there is no window
// system to talk to (no DISPLAY or WAYLAND_DISPLAY, or GLFW cannot initialize): rtvk view needs
// one, rtvk render does not.
class window_system {
 public:
  window_system();
  ~window_system();
  window_system(const window_system&) = delete;
  window_system& operator=(const window_system&) = delete;

  // The instance extensions a Vulkan surface for a window needs here.
  std::vector<std::string> instance_extensions() const;
};

// One window with no client API (Vulkan draws into it), and what happened to it since the last
// poll.
class window {
 public:
  // Throws std::runtime_error naming GLFW's error when the window cannot be made.
  window(const window_system&, int width, int height, const std::string& title);
  ~window();
  window(const window&) = delete;
  window& operator=(const window&) = delete;

  // Handles pending events without waiting, or waits for the next one (while minimized).
  void poll();
  void wait();
  bool should_close() const;
  void request_close();
  // The drawable size in pixels (0 x 0 while minimized).
  void framebuffer_size(int& width, int& height) const;
  // The surface Vulkan presents to (owned by the caller, destroyed with the instance).
  VkSurfaceKHR create_surface(VkInstance instance) const;
  void set_title(const std::string& title);

  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;  // owned
};

}  // namespace rtvk::view
