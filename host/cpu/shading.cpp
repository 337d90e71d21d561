#include "shading.h"

#include <limits>

namespace rtvk {

// The book's recursion as a loop over the shared steps (ray_color.h); shaders/shading.glsl runs
// the same steps, a bounce per trip.
color ray_color(const ray& r_in, const hittable& world, std::span<const material> materials,
                const sky& background, int max_depth, const random_stream& rnd) {
  const double infinity = std::numeric_limits<double>::infinity();
  path_state p = start_path(r_in, rnd);
  while (!path_ends_unlit(p, uint(max_depth))) {
    hit_record rec{};
    if (!world.hit(p.r, t_min, infinity, rec))
      return path_missed(p, background.horizon, background.zenith);
    const material& m = materials[rec.material];
    color c;
    if (path_hit(p, rec, uint(m.type), m.albedo, m.fuzz, m.ir, c)) return c;
  }
  return color(0, 0, 0);  // out of bounces, or no ray: no light gathered
}

color ray_color(const ray& r, const hittable& world) {
  const material normal_shading{};
  return ray_color(r, world, std::span(&normal_shading, 1), sky{}, 1, random_stream{});
}

}  // namespace rtvk
