#pragma once
#include <optional>
#include <span>

#include "hittable.h"
#include "light_sources.h"
#include "light_tree_builder.h"
#include "material.h"
#include "medium.h"
#include "pbr_shading.h"
#include "punctual.h"
#include "random.h"
#include "ray_color.h"
#include "scene.h"
#include "texture.h"

namespace rtvk {

// What shading reads besides the hit: the materials (and the PBR ones' parameters), the textures'
// tables, the media and the lights to sample, as the shared kernels take them (texture.h, medium.h,
// pdf.h). The lights only when `sample_lights` (samples_lights: the third book's mixture), else
// none: plain; under next-event estimation (`nee`), the lamps only (nee.h).
struct scene_shading {
  explicit scene_shading(const scene& s, bool sample_lights = false, bool nee = false);
  bool nee = false;                              // ray_color is ray_color_nee
  std::vector<material> materials;               // by index
  packed_textures textures;                      // records and texels
  perlin_tables perlin;                          // the noise's lattice (the scene's noise seed)
  std::vector<medium_geometry> media;            // in scene order
  std::vector<light_record> lights;              // what scattering aims at; empty: plain sampling
  std::vector<gpu::gpu_light_node> light_nodes;  // nee: the light tree over `lights`' lamps
  std::vector<pbr_record> pbr;            // by material index: a PBR material's parameters (the
                                          // others' are the defaults, unread)
  std::vector<punctual_record> punctual;  // the punctual lights (next-event estimation draws them)
  std::optional<environment_tables> environment;  // what escaping rays see; none: the sky
  texture_tables tables() const {
    return {textures.records.data(), textures.texels.data(), perlin.vectors.data(),
            perlin.perm.data()};
  }
  light_table light_list() const {
    return {lights.data(), uint(lights.size()), light_nodes.empty() ? nullptr : light_nodes.data()};
  }
  punctual_table punctual_list() const { return {punctual.data(), uint(punctual.size())}; }
};

// The color seen along r: bounces through the materials up to max_depth scatter events, and
// returns the sky on a miss. A "normal" material ends the path with the lesson's normal color.
// The loop's body is the shared kernels' (ray_color.h), which the GPU runs too.
color ray_color(const ray& r, const hittable& world, const scene_shading& shading,
                const sky& background, int max_depth, const random_stream& rnd);

// ray_color under next-event estimation (nee_step.cpp; shading.nee): a light sample and a shadow
// ray at every diffuse or PBR vertex, weighed by multiple importance sampling.
color ray_color_nee(const ray& r, const hittable& world, const scene_shading& shading,
                    const sky& background, int max_depth, const random_stream& rnd);

// The lesson's shading: every surface colored by its normal, the sky on a miss.
color ray_color(const ray& r, const hittable& world);

// The sky seen along direction d: by default white at the horizon blending to blue overhead.
inline color sky_color(const vec3& d, const sky& background = sky{}) {
  return sky_color(d, background.horizon, background.zenith);
}

// A PBR material's parameters as the shared kernels read them (pbr_shading.h), an infinite
// attenuation_distance as 0.
pbr_record pbr_record_of(const pbr_material& q);

// One trip of ray_color's loop at a hit on a PBR material (pbr_step.cpp): its volume's absorption,
// alpha and emission as for any material, then its bounce (path_hit_pbr). True: the path ended,
// its color in `c`.
// Under next-event estimation (`nee`: the punctual lights' and the environment's tables beside the
// lamps, `lights`), its bounce is path_hit_pbr_nee.
struct nee_tables {
  punctual_table punctual;
  environment_table environment;
};
bool pbr_step(const scene_shading& shading, const texture_tables& tables, const light_table& lights,
              path_state& p, const hit_record& rec, color& c, const nee_tables* nee = nullptr);

// scatter (scatter.h) for one of the scene's materials.
inline bool scatter(const material& m, const ray& r_in, const hit_record& rec,
                    const random_stream& rnd, color& attenuation, ray& scattered) {
  return scatter(uint(m.type), m.albedo, m.fuzz, m.ir, r_in, rec, rnd, attenuation, scattered);
}

}  // namespace rtvk
