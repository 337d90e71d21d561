#pragma once
// The fast mode's shading: the scene's appearance arrays as the float kernels take them (tables),
// and ray_color's loop over them (fast_shading.cpp), as shaders/shading.glsl runs it.
#include <vector>

#include "environment.h"
#include "fast_render.h"
#include "fast_world.h"
#include "medium.h"
#include "nee_pbr.h"
#include "pbr_shading.h"
#include "punctual.h"
#include "ray_color.h"
#include "texture.h"

namespace rtvk::fast {

// The arrays' lights, textures, media and PBR parameters as kernel records (their fields, in the
// same float), and the tables that point into them.
struct shading_tables {
  shading_tables(const gpu::scene_arrays& a, const fast_settings& s);
  shading_tables(const shading_tables&) = delete;

  const gpu::scene_arrays& arrays;
  std::vector<light_record> lights;
  std::vector<punctual_record> punctual;
  std::vector<texture_record> textures;
  std::vector<real3> perlin_vectors;
  std::vector<medium_geometry> media;
  std::vector<pbr_record> pbr;
  light_table light_list;           // what scattering aims at; count 0: plain sampling
  punctual_table punctual_list;     // next-event estimation's punctual lights
  environment_table environment{};  // texels null: no map
  texture_tables texture_list;
  bool nee = false;
  bool opaque_shadows = false;  // every hit blocks a shadow ray (no see-through, no media)
  real3 horizon, zenith;        // the sky
};

// The color of one path starting along r (the GPU's ray_color_step, looped to its end); `rays`
// counts the rays traced, shadow rays included.
real3 ray_color(const ray& r, const world& w, const shading_tables& t, uint max_depth,
                const random_stream& rnd, std::uint64_t& rays);

}  // namespace rtvk::fast
