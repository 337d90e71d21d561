#pragma once
#include <span>

#include "hittable.h"
#include "material.h"
#include "random.h"
#include "scene.h"

namespace rtvk {

// Hits closer than this are ignored: a scattered ray must not hit its own starting point again
// through rounding ("shadow acne").
inline constexpr double t_min = 0.001;

// The color seen along r: bounces through the materials up to max_depth scatter events, and
// returns the sky on a miss. A "normal" material ends the path with the lesson's normal color.
color ray_color(const ray& r, const hittable& world, std::span<const material> materials,
                const sky& background, int max_depth, const random_stream& rnd);

// The lesson's shading: every surface colored by its normal, the sky on a miss.
color ray_color(const ray& r, const hittable& world);

// The sky seen along direction d: by default white at the horizon blending to blue overhead.
color sky_color(const vec3& d, const sky& background = sky{});

}  // namespace rtvk
