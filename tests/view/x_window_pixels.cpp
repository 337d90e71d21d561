#include "x_window_pixels.h"

#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <bit>

namespace rtvk::test {

image_rgb8 window_pixels(const std::string& display, const std::string& id) {
  image_rgb8 out;
  Display* d = XOpenDisplay(display.c_str());
  if (!d) return out;
  const Window w = std::stoul(id);
  XWindowAttributes a;
  if (XGetWindowAttributes(d, w, &a)) {
    if (XImage* img =
            XGetImage(d, w, 0, 0, unsigned(a.width), unsigned(a.height), AllPlanes, ZPixmap)) {
      const unsigned long masks[3] = {img->red_mask, img->green_mask, img->blue_mask};
      out.width = a.width;
      out.height = a.height;
      out.rgb.reserve(std::size_t(a.width) * std::size_t(a.height) * 3);
      for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
          const unsigned long p = XGetPixel(img, x, y);
          for (const unsigned long m : masks)
            out.rgb.push_back(std::uint8_t((p & m) >> std::countr_zero(m)));
        }
      XDestroyImage(img);
    }
  }
  XCloseDisplay(d);
  return out;
}

}  // namespace rtvk::test
