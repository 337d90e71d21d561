#include "shading.h"

#include "scatter.h"

#include <limits>

namespace rtvk {

color sky_color(const vec3& d, const sky& background) {
  const vec3 unit_direction = unit_vector(d);
  const double t = 0.5 * (unit_direction.y + 1.0);
  return (1.0 - t) * background.horizon + t * background.zenith;
}

// Iterative rather than the book's recursion, so it reads line for line like the shader.
color ray_color(const ray& r_in, const hittable& world, std::span<const material> materials,
                const sky& background, int max_depth, const random_stream& rnd) {
  const double infinity = std::numeric_limits<double>::infinity();
  // A camera gives no ray (a zero direction) where its model sees nothing: black.
  if (r_in.direction() == vec3(0, 0, 0)) return color(0, 0, 0);
  ray r = r_in;
  color throughput(1.0, 1.0, 1.0);
  for (int depth = 0; depth < max_depth; ++depth) {
    hit_record rec;
    if (!world.hit(r, t_min, infinity, rec))
      return throughput * sky_color(r.direction(), background);
    const material& m = materials[std::size_t(rec.material)];
    if (m.type == material_type::normal) return throughput * (0.5 * (rec.normal + color(1, 1, 1)));
    color attenuation;
    ray scattered;
    if (!scatter(m, r, rec, rnd.at_bounce(std::uint32_t(depth + 1)), attenuation, scattered))
      return color(0, 0, 0);
    throughput *= attenuation;
    r = scattered;
  }
  return color(0, 0, 0);  // out of bounces: no light gathered
}

color ray_color(const ray& r, const hittable& world) {
  const material normal_shading{};
  return ray_color(r, world, std::span(&normal_shading, 1), sky{}, 1, random_stream{});
}

}  // namespace rtvk
