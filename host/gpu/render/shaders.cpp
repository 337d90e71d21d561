#include "shaders.h"

// The generated headers declare uint32_t arrays without including <cstdint> themselves.
#include <cstdint>

#include "aov_spv.h"
#include "hit_probe_spv.h"
#include "kernel_probe_spv.h"
#include "light_probe_spv.h"
#include "overlay_spv.h"
#include "probe_spv.h"
#include "render_query_comp_spv.h"
#include "render_ray_rgen_spv.h"
#include "render_spv.h"
#include "rng_probe_spv.h"
#include "rt_miss_rmiss_spv.h"
#include "rt_object_rahit_spv.h"
#include "rt_object_rint_spv.h"
#include "tonemap_spv.h"
#include "world_probe_spv.h"

namespace rtvk::gpu {

std::span<const std::uint32_t> render_shader() {
  return render_spv;
}
std::span<const std::uint32_t> render_query_shader() {
  return render_query_comp_spv;
}
ray_shaders render_ray_shaders() {
  return {render_ray_rgen_spv, rt_miss_rmiss_spv, rt_object_rint_spv, rt_object_rahit_spv};
}
std::span<const std::uint32_t> tonemap_shader() {
  return tonemap_spv;
}
std::span<const std::uint32_t> overlay_shader() {
  return overlay_spv;
}
std::span<const std::uint32_t> probe_shader() {
  return probe_spv;
}
std::span<const std::uint32_t> rng_probe_shader() {
  return rng_probe_spv;
}
std::span<const std::uint32_t> hit_probe_shader() {
  return hit_probe_spv;
}
std::span<const std::uint32_t> aov_shader() {
  return aov_spv;
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

}  // namespace rtvk::gpu
