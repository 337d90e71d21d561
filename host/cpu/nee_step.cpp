// ray_color under next-event estimation (--sampling nee; shaders/shared/lights/nee.h), in a
// translation unit of its own like pbr_step.cpp: the books' loop in shading.cpp keeps the code
// GCC makes of it. The steps are the shared kernels'; the GPU runs the same (shaders/shading.glsl),
// there tracing each shadow ray in a trip of its own.
#include <limits>

#include "nee_pbr.h"
#include "shading.h"

namespace rtvk {
namespace {

// Traces p's pending shadow ray to its end: its light is added where nothing blocks it, and the
// see-through surfaces it meets let it by as they let paths by.
void trace_shadow(const hittable& world, const scene_shading& shading, const texture_tables& tables,
                  path_state& p) {
  while (p.shadow_reach > 0) {
    hit_record rec{};
    if (!world.hit(p.shadow, t_min, p.shadow_reach, rec)) {
      shadow_unblocked(p);
      return;
    }
    const material& m = shading.materials[rec.material];
    const uint flags = material_flags(m);
    const double alpha = (flags & RTVK_MATERIAL_SEE_THROUGH) != 0u
                             ? surface_alpha(tables, m.opacity, uint(m.texture), rec)
                             : 1.0;
    shadow_meets(p, rec, uint(m.type), flags, alpha, m.alpha_cutoff);
  }
}

}  // namespace

color ray_color_nee(const ray& r_in, const hittable& world, const scene_shading& shading,
                    const sky& background, int max_depth, const random_stream& rnd) {
  const double infinity = std::numeric_limits<double>::infinity();
  const texture_tables tables = shading.tables();
  const light_table lights = shading.light_list();
  const nee_tables nee{shading.punctual_list(),
                       shading.environment ? shading.environment->view() : environment_table{}};
  const punctual_table& punctual = nee.punctual;
  const environment_table& env = nee.environment;
  path_state p = start_path(r_in, rnd);
  while (!path_ends_unlit(p, uint(max_depth))) {
    hit_record rec{};
    if (!world.hit(p.r, t_min, infinity, rec))
      return path_missed_nee(lights, punctual, env, p, background.horizon, background.zenith);
    const material& m = shading.materials[rec.material];
    color c;
    if (m.type == material_type::pbr) {
      if (pbr_step(shading, tables, lights, p, rec, c, &nee)) return c;
      trace_shadow(world, shading, tables, p);
      continue;
    }
    const uint flags = material_flags(m);
    if ((flags & RTVK_MATERIAL_SEE_THROUGH) != 0u &&
        path_passes(p, rec, uint(m.type), flags,
                    surface_alpha(tables, m.opacity, uint(m.texture), rec), m.alpha_cutoff))
      continue;
    if ((flags & RTVK_MATERIAL_EMISSIVE) != 0u)
      path_emits(p, m.emission * emission_color(tables, uint(m.emission_texture), rec));
    const color albedo = material_color(tables, m.albedo, uint(m.texture), rec) * color(rec.color);
    if (path_hit_nee(lights, punctual, env, p, rec, uint(m.type), flags, albedo, m.fuzz, m.ir, c))
      return c;
    trace_shadow(world, shading, tables, p);
  }
  return p.radiance;  // out of bounces, or ended after its last shadow ray
}

}  // namespace rtvk
