#include "render_cpu.h"

#include "random.h"
#include "shading.h"

namespace rtvk {

framebuffer render_cpu(const camera& cam, const scene& s, const render_settings& rs,
                       const progress_callback& progress) {
  const int width = cam.image_width();
  const int height = cam.image_height();
  const hittable_list world = make_world(s);
  const std::vector<material> materials = scene_materials(s);
  framebuffer fb(width, height);
  for (int y = 0; y < height; ++y) {
    const int j = height - 1 - y;  // the lesson counts rows from the bottom
    for (int i = 0; i < width; ++i) {
      color sum(0, 0, 0);
      for (int sample = 0; sample < rs.spp; ++sample) {
        const random_stream rnd{rs.seed, std::uint32_t(y) * std::uint32_t(width) + std::uint32_t(i),
                                std::uint32_t(sample), 0};
        const double u = pixel_coordinate(rs.jitter ? i + rnd(dim_jitter_u) : i, width);
        const double v = pixel_coordinate(rs.jitter ? j + rnd(dim_jitter_v) : j, height);
        const glm::dvec2 lens = cam.lens_radius() > 0
                                    ? random_in_unit_disk(rnd(dim_lens_a), rnd(dim_lens_b))
                                    : glm::dvec2(0, 0);
        sum += ray_color(cam.get_ray(u, v, lens), world, materials, s.sky, rs.max_depth, rnd);
      }
      fb.at(i, y) = divide(sum, rs.spp);
    }
    if (progress) progress(y + 1);
  }
  return fb;
}

}  // namespace rtvk
