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
std::span<const std::uint32_t> tonemap_shader();       // tonemap.comp
std::span<const std::uint32_t> overlay_shader();       // overlay.comp
std::span<const std::uint32_t> probe_shader();         // probe.comp
std::span<const std::uint32_t> rng_probe_shader();     // rng_probe.comp
std::span<const std::uint32_t> hit_probe_shader();     // hit_probe.comp
std::span<const std::uint32_t> world_probe_shader();   // world_probe.comp
std::span<const std::uint32_t> aov_shader();           // aov.comp
std::span<const std::uint32_t> kernel_probe_shader();  // kernel_probe.comp
std::span<const std::uint32_t> light_probe_shader();   // light_probe.comp

}  // namespace rtvk::gpu
