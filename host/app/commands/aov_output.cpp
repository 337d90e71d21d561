#include "aov_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace rtvk {

aov_image aov_from(const std::vector<gpu::gpu_aov>& found, const object_ids& ids, unsigned which,
                   const render_window& win) {
  aov_image a;
  a.which = which;
  a.width = win.width;
  a.height = win.height;
  const std::size_t n = found.size();
  if (which & aov_depth) a.distance.resize(n), a.depth.resize(n);
  if (which & aov_normal) a.normal.resize(3 * n);
  if (which & aov_albedo) a.albedo.resize(3 * n);
  if (which & aov_object_id) a.object_id.resize(n);
  if (which & aov_material_id) a.material_id.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const gpu::gpu_aov& f = found[k];
    if (which & aov_depth) {
      a.distance[k] = f.distance;
      a.depth[k] = f.depth;
    }
    for (int c = 0; c < 3; ++c) {
      if (which & aov_normal) a.normal[3 * k + std::size_t(c)] = f.normal[c];
      if (which & aov_albedo) a.albedo[3 * k + std::size_t(c)] = f.albedo[c];
    }
    if (which & aov_object_id) a.object_id[k] = f.hit ? ids.of(f.object, f.instance) : 0;
    if (which & aov_material_id) a.material_id[k] = f.hit ? f.material + 1 : 0;
  }
  return a;
}

std::string aov_path(const std::string& output, aov_bit which) {
  std::filesystem::path p(output);
  p.replace_extension();
  return p.string() + "." + aov_name(which) + ".exr";
}

bool aovs_agree(const std::vector<gpu::gpu_aov>& gpu, const std::vector<gpu::gpu_aov>& cpu,
                const object_ids& ids, const std::string& label) {
  std::size_t differ = 0;
  double worst = 0;
  for (std::size_t k = 0; k < std::min(gpu.size(), cpu.size()); ++k) {
    const gpu::gpu_aov &g = gpu[k], &c = cpu[k];
    if (g.hit != c.hit || (g.hit && (ids.of(g.object, g.instance) != ids.of(c.object, c.instance) ||
                                     g.material != c.material))) {
      ++differ;
      continue;
    }
    if (g.hit)
      worst = std::max(worst, double(std::abs(g.distance - c.distance)) /
                                  std::max(1.0, double(std::abs(c.distance))));
  }
  const double share = gpu.empty() ? 0 : double(differ) / double(gpu.size());
  const bool ok = gpu.size() == cpu.size() && share <= 0.001 && worst <= 1e-4;
  std::fprintf(stderr,
               "rtvk: %sgpu vs cpu AOVs: %s -- %zu of %zu pixels hit another object or material "
               "(allowed 0.1%%), largest distance difference %.2g relative (allowed 1e-4)\n",
               label.c_str(), ok ? "alike" : "DIFFERENT", differ, gpu.size(), worst);
  return ok;
}

}  // namespace rtvk
