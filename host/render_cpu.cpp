#include "render_cpu.h"

#include "shading.h"

namespace rtvk {

framebuffer render_cpu(const camera& cam, const hittable& world) {
  const int width = cam.image_width();
  const int height = cam.image_height();
  framebuffer fb(width, height);
  for (int j = height - 1; j >= 0; --j) {
    const double v = pixel_coordinate(j, height);
    for (int i = 0; i < width; ++i) {
      const double u = pixel_coordinate(i, width);
      fb.at(i, height - 1 - j) = ray_color(cam.get_ray(u, v), world);
    }
  }
  return fb;
}

}  // namespace rtvk
