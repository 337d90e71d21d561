#include "aov_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "errors.h"

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
                const object_ids& ids, int width, const std::string& label) {
  const auto key = [&](const gpu::gpu_aov& a) {
    return a.hit ? (std::uint64_t(ids.of(a.object, a.instance)) << 32) | a.material
                 : ~std::uint64_t(0);
  };
  const std::size_t n = std::min(gpu.size(), cpu.size()), w = std::size_t(std::max(width, 1));
  // Whether the CPU's pixel k has a neighbor (of 8) that shows something else.
  const auto on_edge = [&](std::size_t k) {
    const std::size_t x = k % w, y = k / w;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::size_t nx = x + std::size_t(dx), ny = y + std::size_t(dy);
        if (nx >= w || ny * w + nx >= n) continue;
        if (key(cpu[ny * w + nx]) != key(cpu[k])) return true;
      }
    return false;
  };
  std::size_t on_edges = 0, elsewhere = 0;
  double worst = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const gpu::gpu_aov &g = gpu[k], &c = cpu[k];
    if (key(g) != key(c)) {
      ++(on_edge(k) ? on_edges : elsewhere);
    } else if (g.hit) {
      worst = std::max(worst, double(std::abs(g.distance - c.distance)) /
                                  std::max(1.0, double(std::abs(c.distance))));
    }
  }
  const bool ok = gpu.size() == cpu.size() && elsewhere == 0 && worst <= 1e-4;
  std::fprintf(stderr,
               "rtvk: %sgpu vs cpu AOVs: %s -- ids and materials differ at %zu of %zu pixels off "
               "the id image's edges (allowed 0) and %zu on them; largest distance difference "
               "%.2g relative (allowed 1e-4)\n",
               label.c_str(), ok ? "alike" : "DIFFERENT", elsewhere, n, on_edges, worst);
  return ok;
}

unsigned aov_flag(const std::string& list) {
  if (list.empty()) return 0;
  const std::optional<unsigned> parsed = parse_aov_list(list);
  if (!parsed)
    throw usage_error("--aov " + list + ": expected a comma-separated list of " + aov_names());
  return *parsed;
}

}  // namespace rtvk
