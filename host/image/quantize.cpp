#include "quantize.h"

namespace rtvk {

image_rgb8 quantize(const framebuffer& fb, double gamma) {
  image_rgb8 img{fb.width(), fb.height(), {}};
  img.rgb.reserve(img.size_bytes());
  for (int y = 0; y < fb.height(); ++y) {
    for (int x = 0; x < fb.width(); ++x) {
      const color& c = fb.at(x, y);
      img.rgb.push_back(to_byte(encode_gamma(c.r, gamma)));
      img.rgb.push_back(to_byte(encode_gamma(c.g, gamma)));
      img.rgb.push_back(to_byte(encode_gamma(c.b, gamma)));
    }
  }
  return img;
}

image_rgb8 quantize(const framebuffer& fb, const display_encoding& e) {
  if (e.transform == view_transform::gamma && e.exposure == 0) return quantize(fb, e.gamma);
  image_rgb8 img{fb.width(), fb.height(), {}};
  img.rgb.reserve(img.size_bytes());
  for (int y = 0; y < fb.height(); ++y) {
    for (int x = 0; x < fb.width(); ++x) {
      const color& c = fb.at(x, y);
      for (std::uint8_t byte : encode_color(c.r, c.g, c.b, e)) img.rgb.push_back(byte);
    }
  }
  return img;
}

}  // namespace rtvk
