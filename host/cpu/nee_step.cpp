// ray_color under next-event estimation (--sampling nee; shaders/shared/lights/nee.h), in a
// translation unit of its own like pbr_step.cpp: the books' loop in shading.cpp keeps the code
// GCC makes of it. The steps are the shared kernels'; the GPU runs the same (shaders/shading.glsl),
// there tracing each shadow ray in a trip of its own.
#include <limits>

#include "nee_pbr.h"
#include "shading.h"

namespace rtvk {
namespace {

// Whether a medium scatters p's shadow ray before t_end (the world's hit or the ray's reach).
bool shadow_scattered(const scene_shading& shading, const path_state& p, double t_end) {
  const random_stream s = shadow_stream(p);
  hit_record rec{};
  for (const medium_geometry& m : shading.media)
    if (hit_medium(m, p.shadow, t_min, t_end, medium_random(s, m.index, dim_shadow_medium), rec))
      return true;
  return false;
}

// Traces p's pending shadow ray to its end: its light is added where nothing blocks it, and the
// see-through surfaces it meets let it by as they let paths by; a medium that scatters it blocks
// it.
void trace_shadow(const hittable& world, const scene_shading& shading, const texture_tables& tables,
                  path_state& p) {
  while (p.shadow_reach > 0) {
    hit_record rec{};
    const bool hit = world.hit(p.shadow, t_min, p.shadow_reach, rec);
    if (shadow_scattered(shading, p, hit ? rec.t : p.shadow_reach)) {
      shadow_blocked(p);
      return;
    }
    if (!hit) {
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
  path_state p = start_path(r_in, rnd, uint(max_depth));
  while (!path_ends_unlit(p, uint(max_depth))) {
    hit_record rec{};
    bool hit = world.hit(p.r, t_min, infinity, rec);
    if (!shading.media.empty()) {  // as ray_color: the media within the world's hit
      const random_stream s = at_bounce(p.s, p.depth + 1u);
      for (const medium_geometry& m : shading.media)
        if (hit_medium(m, p.r, t_min, hit ? rec.t : infinity, medium_random(s, m.index, dim_medium),
                       rec))
          hit = true;
    }
    if (!hit)
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
