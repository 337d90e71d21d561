#include "render_aov.h"

#include <limits>

#include "aov.h"
#include "bvh_world.h"
#include "parallel.h"
#include "shading.h"
#include "texture.h"

namespace rtvk {

std::vector<gpu::gpu_aov> render_aov_cpu(const camera& cam, const scene& s,
                                         const render_window& win, int threads) {
  // Always the BVH: its ties go to the same object as a scan of every object, so the ids are
  // the ones any --accel draws.
  return render_aov_cpu(cam, bvh_world(s, threads), scene_shading(s), win, threads);
}

std::vector<gpu::gpu_aov> render_aov_cpu(const camera& cam, const bvh_world& world,
                                         const scene_shading& shading, const render_window& win,
                                         int threads) {
  const texture_tables tables = shading.tables();
  const camera_frame& f = cam.frame();
  const uint width = uint(cam.image_width()), height = uint(cam.image_height());
  std::vector<gpu::gpu_aov> out(std::size_t(win.width) * std::size_t(win.height));
  parallel_for(std::size_t(win.height), threads, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < win.width; ++x) {
        const uint i = uint(win.x + x), j = height - 1u - uint(win.y + int(y));
        const ray r = center_ray(f, width, height, i, j);
        gpu::gpu_aov& a = out[y * std::size_t(win.width) + std::size_t(x)];
        a = {};
        a.distance = a.depth = std::numeric_limits<float>::infinity();
        hit_record rec{};
        std::uint32_t object = 0, instance = 0;
        // The first surface that counts (aov.h's aov_counts): those a ray passes are walked
        // through, their lengths summed.
        ray walk = r;
        double passed = 0;
        bool found = false;
        for (uint k = 0; k <= max_passes && r.direction != vec3(0); ++k) {
          if (!world.hit_which(walk, 0.001, std::numeric_limits<double>::infinity(), rec, object,
                               instance))
            break;
          const material& m = shading.materials[rec.material];
          found =
              k == max_passes ||
              aov_counts(uint(m.type), material_flags(m), rec,
                         surface_alpha(tables, m.opacity, uint(m.texture), rec), m.alpha_cutoff);
          if (found) break;
          passed += aov_distance(walk, rec);
          walk.origin = scatter_origin(rec, walk.direction);
        }
        if (!found) continue;
        const material& m = shading.materials[rec.material];
        const color c = material_color(tables, m.albedo, uint(m.texture), rec) * color(rec.color);
        a.normal = glm::vec3(rec.normal);
        a.albedo = glm::vec3(aov_albedo(uint(m.type), c, rec));
        a.distance = float(passed + aov_distance(walk, rec));
        a.depth = float(aov_depth(f.origin, f.axis_w, rec));
        a.object = object;
        a.instance = instance;
        a.material = rec.material;
        a.hit = 1;
      }
  });
  return out;
}

}  // namespace rtvk
