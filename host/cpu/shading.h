#pragma once
#include <span>

#include "hittable.h"
#include "material.h"
#include "random.h"
#include "ray_color.h"
#include "scene.h"

namespace rtvk {

// The color seen along r: bounces through the materials up to max_depth scatter events, and
// returns the sky on a miss. A "normal" material ends the path with the lesson's normal color.
// The loop's body is the shared kernels' (ray_color.h), which the GPU runs too.
color ray_color(const ray& r, const hittable& world, std::span<const material> materials,
                const sky& background, int max_depth, const random_stream& rnd);

// The lesson's shading: every surface colored by its normal, the sky on a miss.
color ray_color(const ray& r, const hittable& world);

// The sky seen along direction d: by default white at the horizon blending to blue overhead.
inline color sky_color(const vec3& d, const sky& background = sky{}) {
  return sky_color(d, background.horizon, background.zenith);
}

// scatter (scatter.h) for one of the scene's materials.
inline bool scatter(const material& m, const ray& r_in, const hit_record& rec,
                    const random_stream& rnd, color& attenuation, ray& scattered) {
  return scatter(uint(m.type), m.albedo, m.fuzz, m.ir, r_in, rec, rnd, attenuation, scattered);
}

}  // namespace rtvk
