#include "shaders.h"

// The generated headers declare uint32_t arrays without including <cstdint> themselves.
#include <cstdint>

#include "aov_spv.h"
#include "render_query_comp_spv.h"
#include "render_ray_rgen_spv.h"
#include "render_spv.h"
#include "rt_miss_rmiss_spv.h"
#include "rt_object_rahit_spv.h"
#include "rt_object_rint_spv.h"
#include "tonemap_spv.h"

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
std::span<const std::uint32_t> aov_shader() {
  return aov_spv;
}

}  // namespace rtvk::gpu
