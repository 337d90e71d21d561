#pragma once
#include <cstdint>
#include <span>

namespace rtvk::gpu {

// The probe shaders' SPIR-V, compiled at build time and embedded in the tests' probe library
// (never in rtvk: Architecture.TheRtvkBinaryCarriesNoTestProbes).
std::span<const std::uint32_t> probe_shader();              // probe.comp
std::span<const std::uint32_t> rng_probe_shader();          // rng_probe.comp
std::span<const std::uint32_t> hit_probe_shader();          // hit_probe.comp
std::span<const std::uint32_t> world_probe_shader();        // world_probe.comp
std::span<const std::uint32_t> kernel_probe_shader();       // kernel_probe.comp
std::span<const std::uint32_t> light_probe_shader();        // light_probe.comp
std::span<const std::uint32_t> pbr_probe_shader();          // pbr_probe.comp
std::span<const std::uint32_t> light_tree_probe_shader();   // light_tree_probe.comp
std::span<const std::uint32_t> punctual_probe_shader();     // punctual_probe.comp
std::span<const std::uint32_t> environment_probe_shader();  // environment_probe.comp
std::span<const std::uint32_t> sobol_probe_shader();        // sobol_probe.comp

}  // namespace rtvk::gpu
