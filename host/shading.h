#pragma once
#include "hittable.h"

namespace rtvk {

// The lesson's shading: a hit is colored by its normal, a miss by the sky gradient.
color ray_color(const ray& r, const hittable& world);

// The sky seen along direction d: white at the horizon blending to blue overhead.
color sky_color(const vec3& d);

}  // namespace rtvk
