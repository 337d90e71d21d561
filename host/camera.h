#pragma once
#include "ray.h"

namespace rtvk {

// The largest image side rtvk accepts, in pixels.
inline constexpr int max_image_side = 65536;

// A pinhole camera at the origin looking down -z, exactly as the lesson designs it: everything
// a ray needs is precomputed once, so get_ray is three multiply-adds.
class camera {
 public:
  // Throws std::invalid_argument for an aspect ratio that is not finite and positive, a width
  // outside [1, max_image_side], or a derived height above max_image_side.
  explicit camera(double aspect_ratio = 16.0 / 9.0, int image_width = 400);

  // The ray through normalized image coordinates (u, v): (0, 0) is the lower-left corner of the
  // viewport, (1, 1) the upper-right.
  ray get_ray(double u, double v) const {
    return ray(origin_, lower_left_ + u * horizontal_ + v * vertical_ - origin_);
  }

  double aspect_ratio() const { return aspect_ratio_; }
  int image_width() const { return image_width_; }
  int image_height() const { return image_height_; }
  const point3& origin() const { return origin_; }
  const vec3& horizontal() const { return horizontal_; }
  const vec3& vertical() const { return vertical_; }
  const point3& lower_left() const { return lower_left_; }

 private:
  double aspect_ratio_;  // image width / height
  int image_width_;      // pixels
  int image_height_;     // pixels, max(1, int(width / aspect))
  point3 origin_;        // eye position, scene units
  vec3 horizontal_;      // full viewport width as a vector, scene units
  vec3 vertical_;        // full viewport height as a vector, scene units
  point3 lower_left_;    // lower-left corner of the viewport, scene units
};

}  // namespace rtvk
