#include "camera.h"

#include "format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rtvk {
namespace {

int checked_height(double aspect_ratio, int image_width) {
  if (!std::isfinite(aspect_ratio) || aspect_ratio <= 0)
    throw std::invalid_argument("aspect ratio must be finite and > 0, got " +
                                format_number(aspect_ratio));
  if (image_width < 1 || image_width > max_image_side)
    throw std::invalid_argument("image width must be in [1, " + std::to_string(max_image_side) +
                                "], got " + std::to_string(image_width));
  // Checked in double first: int() of an out-of-range value is undefined behaviour.
  const double height = image_width / aspect_ratio;
  if (height >= max_image_side + 1.0)
    throw std::invalid_argument("aspect ratio " + format_number(aspect_ratio) + " at width " +
                                std::to_string(image_width) + " gives an image height above " +
                                std::to_string(max_image_side));
  return std::max(1, static_cast<int>(height));
}

}  // namespace

camera::camera(double aspect_ratio, int image_width)
    : aspect_ratio_(aspect_ratio),
      image_width_(image_width),
      image_height_(checked_height(aspect_ratio, image_width)) {
  const double viewport_height = 2.0;
  const double viewport_width = aspect_ratio * viewport_height;
  const double focal_length = 1.0;

  origin_ = point3(0, 0, 0);
  horizontal_ = vec3(viewport_width, 0.0, 0.0);
  vertical_ = vec3(0.0, viewport_height, 0.0);
  lower_left_ = origin_ - divide(horizontal_, 2) - divide(vertical_, 2) - vec3(0, 0, focal_length);
}

}  // namespace rtvk
