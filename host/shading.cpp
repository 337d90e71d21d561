#include "shading.h"

#include <limits>

namespace rtvk {

color sky_color(const vec3& d) {
  const vec3 unit_direction = unit_vector(d);
  const double t = 0.5 * (unit_direction.y + 1.0);
  return (1.0 - t) * color(1.0, 1.0, 1.0) + t * color(0.5, 0.7, 1.0);
}

color ray_color(const ray& r, const hittable& world) {
  hit_record rec;
  if (world.hit(r, 0, std::numeric_limits<double>::infinity(), rec))
    return 0.5 * (rec.normal + color(1, 1, 1));
  return sky_color(r.direction());
}

}  // namespace rtvk
