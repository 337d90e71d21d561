#pragma once
#include <array>

#include <glm/vec2.hpp>

#include "camera.h"
#include "context.h"
#include "shared_types.h"

namespace rtvk::gpu {

// Runs probe.comp: the GPU reports the camera uniform buffer it received and the ray directions
// get_ray gives for `uv`, so tests can check the GPU's camera against the CPU's.
probe_io run_probe(gpu_context& ctx, const camera& cam,
                   const std::array<glm::vec2, RTVK_PROBE_POINTS>& uv);

}  // namespace rtvk::gpu
