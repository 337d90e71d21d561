#include "probe_shaders.h"

// The generated headers declare uint32_t arrays without including <cstdint> themselves.
#include <cstdint>

#include "environment_probe_spv.h"
#include "hit_probe_spv.h"
#include "kernel_probe_spv.h"
#include "light_probe_spv.h"
#include "light_tree_probe_spv.h"
#include "pbr_probe_spv.h"
#include "probe_spv.h"
#include "punctual_probe_spv.h"
#include "rng_probe_spv.h"
#include "sobol_probe_spv.h"
#include "world_probe_spv.h"

namespace rtvk::gpu {

std::span<const std::uint32_t> probe_shader() {
  return probe_spv;
}
std::span<const std::uint32_t> rng_probe_shader() {
  return rng_probe_spv;
}
std::span<const std::uint32_t> hit_probe_shader() {
  return hit_probe_spv;
}
std::span<const std::uint32_t> world_probe_shader() {
  return world_probe_spv;
}
std::span<const std::uint32_t> kernel_probe_shader() {
  return kernel_probe_spv;
}
std::span<const std::uint32_t> light_probe_shader() {
  return light_probe_spv;
}
std::span<const std::uint32_t> pbr_probe_shader() {
  return pbr_probe_spv;
}
std::span<const std::uint32_t> light_tree_probe_shader() {
  return light_tree_probe_spv;
}
std::span<const std::uint32_t> punctual_probe_shader() {
  return punctual_probe_spv;
}

std::span<const std::uint32_t> environment_probe_shader() {
  return environment_probe_spv;
}

std::span<const std::uint32_t> sobol_probe_shader() {
  return sobol_probe_spv;
}

}  // namespace rtvk::gpu
