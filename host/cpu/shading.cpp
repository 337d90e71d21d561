#include "shading.h"

#include <limits>

namespace rtvk {

scene_shading::scene_shading(const scene& s, bool sample_lights, bool nee_)
    : nee(nee_),
      materials(scene_materials(s)),
      textures(pack_textures(s.textures)),
      perlin(make_perlin(s.noise_seed)) {
  for (std::size_t k = 0; k < s.media.size(); ++k)
    media.push_back(geometry_of(s.media[k], std::uint32_t(k)));
  if (sample_lights) lights = scene_lights(s);
  if (nee) lights = scene_lamps(s);
  if (nee) light_nodes = build_light_tree(lights, s.motion);
  if (nee) punctual = punctual_records(s.punctual_lights);
  for (const material& m : materials) pbr.push_back(pbr_record_of(m.pbr));
  if (s.environment) environment.emplace(*s.environment);
}

namespace {

// p.r escaped: the sky, or the environment map where the scene has one and p sees it.
color missed(const path_state& p, const scene_shading& shading, const sky& background) {
  if (shading.environment) {
    const environment_table env = shading.environment->view();
    if (path_sees_environment(p, environment_visible(env)))
      return path_missed_into(p, environment_radiance(env, p.r.direction));
  }
  return path_missed(p, background.horizon, background.zenith);
}

}  // namespace

// The book's recursion as a loop over the shared steps (ray_color.h); shaders/shading.glsl runs
// the same steps, a bounce per trip. The media are tested after the world, within its hit: the
// nearest of the world's hit and the media's scattering points wins.
color ray_color(const ray& r_in, const hittable& world, const scene_shading& shading,
                const sky& background, int max_depth, const random_stream& rnd) {
  if (shading.nee) return ray_color_nee(r_in, world, shading, background, max_depth, rnd);
  const double infinity = std::numeric_limits<double>::infinity();
  const texture_tables tables = shading.tables();
  const light_table lights = shading.light_list();
  path_state p = start_path(r_in, rnd, uint(max_depth));
  while (!path_ends_unlit(p, uint(max_depth))) {
    hit_record rec{};
    bool hit = world.hit(p.r, t_min, infinity, rec);
    if (!shading.media.empty()) {
      const random_stream s = at_bounce(p.s, p.depth + 1u);
      for (const medium_geometry& m : shading.media)
        if (hit_medium(m, p.r, t_min, hit ? rec.t : infinity, medium_random(s, m.index, dim_medium),
                       rec))
          hit = true;
    }
    if (!hit) return missed(p, shading, background);
    const material& m = shading.materials[rec.material];
    if (m.type == material_type::pbr) {
      color c;
      if (pbr_step(shading, tables, lights, p, rec, c)) return c;
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
    color c;
    if (path_hit(lights, p, rec, uint(m.type), flags, albedo, m.fuzz, m.ir, c)) return c;
  }
  return p.radiance;  // out of bounces, or no ray: the light gathered on the way
}

color ray_color(const ray& r, const hittable& world) {
  static const scene_shading normal_shading = [] {
    scene s;
    s.materials.push_back({"normal", material{}});
    return scene_shading(s);
  }();
  return ray_color(r, world, normal_shading, sky{}, 1, random_stream{});
}

}  // namespace rtvk
