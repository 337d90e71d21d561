#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <stdexcept>

#include "errors.h"
#include "vk_error.h"

namespace rtvk::view {
namespace {

std::string last_glfw_error() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  if (code == GLFW_NO_ERROR) return "no error reported";
  return description ? description : "GLFW error " + std::to_string(code);
}

bool has_display() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 && *x11) || (wayland && *wayland);
}

}  // namespace

window_system::window_system() {
  const std::string needs = "rtvk view needs a window system; rtvk render works without one";
  if (!has_display())
    throw usage_error("no display (DISPLAY and WAYLAND_DISPLAY are unset): " + needs);
  if (glfwInit() != GLFW_TRUE)
    throw usage_error("the window system cannot be used (" + last_glfw_error() + "): " + needs);
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw usage_error("GLFW finds no Vulkan loader to show a window with: " + needs);
  }
}

window_system::~window_system() {
  glfwTerminate();
}

std::vector<std::string> window_system::instance_extensions() const {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names)
    throw std::runtime_error("the window system offers no Vulkan surface (" + last_glfw_error() +
                             ")");
  return std::vector<std::string>(names, names + count);
}

window::window(const window_system&, int width, int height, const std::string& title) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw std::runtime_error("glfwCreateWindow: " + last_glfw_error());
  glfwSetWindowUserPointer(window_, this);
  glfwSetCursorPosCallback(window_, on_cursor);
  glfwSetMouseButtonCallback(window_, on_button);
  glfwSetScrollCallback(window_, on_scroll);
  glfwSetKeyCallback(window_, on_key);
}

void window::on_cursor(GLFWwindow* w, double x, double y) {
  auto* self = static_cast<window*>(glfwGetWindowUserPointer(w));
  if (self->cursor_known_) {
    const int buttons[3] = {GLFW_MOUSE_BUTTON_LEFT, GLFW_MOUSE_BUTTON_RIGHT,
                            GLFW_MOUSE_BUTTON_MIDDLE};
    for (int b = 0; b < 3; ++b)
      if (glfwGetMouseButton(w, buttons[b]) == GLFW_PRESS) {
        self->input_.drag[b][0] += x - self->cursor_x_;
        self->input_.drag[b][1] += y - self->cursor_y_;
      }
  }
  self->cursor_x_ = x;
  self->cursor_y_ = y;
  self->cursor_known_ = true;
}

void window::on_button(GLFWwindow* w, int button, int action, int) {
  auto* self = static_cast<window*>(glfwGetWindowUserPointer(w));
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  self->cursor_x_ = x;  // drags start where the button went down
  self->cursor_y_ = y;
  self->cursor_known_ = true;
  if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS &&
      glfwGetKey(w, GLFW_KEY_F) == GLFW_PRESS) {
    self->input_.focus_click = true;
    self->input_.click_x = x;
    self->input_.click_y = y;
  }
}

void window::on_scroll(GLFWwindow* w, double, double dy) {
  static_cast<window*>(glfwGetWindowUserPointer(w))->input_.scroll += dy;
}

void window::on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action == GLFW_PRESS || action == GLFW_REPEAT)
    static_cast<window*>(glfwGetWindowUserPointer(w))->input_.keys.push_back(key);
}

void window::window_size(int& width, int& height) const {
  glfwGetWindowSize(window_, &width, &height);
}

window_input window::take_input() {
  window_input taken = std::move(input_);
  input_ = {};
  return taken;
}

window::~window() {
  glfwDestroyWindow(window_);
}

void window::poll() {
  glfwPollEvents();
}
void window::wait() {
  glfwWaitEventsTimeout(0.1);
}
bool window::should_close() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}
void window::request_close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void window::framebuffer_size(int& width, int& height) const {
  glfwGetFramebufferSize(window_, &width, &height);
}

bool window::minimized() const {
  int width = 0, height = 0;
  framebuffer_size(width, height);
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE || width == 0 || height == 0;
}

VkSurfaceKHR window::create_surface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  gpu::vk_check(glfwCreateWindowSurface(instance, window_, nullptr, &surface),
                "glfwCreateWindowSurface");
  return surface;
}

void window::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

}  // namespace rtvk::view
