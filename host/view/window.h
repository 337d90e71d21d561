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

// What the user did since the input was last taken.
struct window_input {
  double drag[3][2] = {};    // per mouse button (left, right, middle): cursor motion while held,
                             // window pixels, x to the right and y down
  double scroll = 0;         // wheel steps, positive away from the user
  std::vector<int> keys;     // GLFW key codes pressed (or auto-repeated), in order
  bool focus_click = false;  // the left button was pressed while F was held ...
  double click_x = 0, click_y = 0;  // ... here, window pixels from the top left
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
  // The drawable size in pixels (0 x 0 while minimized on some systems, unchanged on X11).
  void framebuffer_size(int& width, int& height) const;
  // Iconified by the window manager, or with nothing to draw into.
  bool minimized() const;
  // The surface Vulkan presents to (owned by the caller, destroyed with the instance).
  VkSurfaceKHR create_surface(VkInstance instance) const;
  void set_title(const std::string& title);
  // The window's size in screen coordinates (what cursor positions are measured in).
  void window_size(int& width, int& height) const;
  // Returns what happened since the last call, and forgets it.
  window_input take_input();

  GLFWwindow* handle() const { return window_; }

 private:
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_button(GLFWwindow* w, int button, int action, int mods);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);

  GLFWwindow* window_ = nullptr;        // owned
  window_input input_;                  // collected by the callbacks
  double cursor_x_ = 0, cursor_y_ = 0;  // last cursor position
  bool cursor_known_ = false;           // cursor_x_/y_ hold a position
};

}  // namespace rtvk::view
