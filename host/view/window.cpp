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
