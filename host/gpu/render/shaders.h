#pragma once
#include <cstdint>
#include <span>

#include "ray_pipeline.h"

namespace rtvk::gpu {

// SPIR-V compiled from shaders/ at build time and embedded in the binary.
std::span<const std::uint32_t> render_shader();        // render.comp
std::span<const std::uint32_t> render_query_shader();  // render_query.comp
// render_ray.rgen, rt_miss.rmiss, rt_object.rint, rt_object.rahit
ray_shaders render_ray_shaders();
std::span<const std::uint32_t> tonemap_shader();  // tonemap.comp
std::span<const std::uint32_t> aov_shader();      // aov.comp

}  // namespace rtvk::gpu
