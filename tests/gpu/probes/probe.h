#pragma once
#include <array>
#include <cstdint>
#include <glm/vec4.hpp>
#include <vector>

#include "camera.h"
#include "context.h"
#include "lights_types.h"
#include "probe_types.h"
#include "scene.h"
#include "shared_types.h"

namespace rtvk::gpu {

// Runs probe.comp: the GPU reports the rays get_ray gives for each (u, v, lens_x, lens_y), so
// tests can check the GPU's camera against the CPU's.
probe_io run_probe(gpu_context& ctx, const camera& cam,
                   const std::array<glm::vec4, RTVK_PROBE_POINTS>& uv_lens);

// Runs rng_probe.comp: fills `bits` and `value` of each entry on the GPU (seed 0x5eed).
std::vector<rng_probe_entry> run_rng_probe(gpu_context& ctx, std::vector<rng_probe_entry> entries);

// Runs sobol_probe.comp: fills the outputs of each entry with sobol.h's numbers (seed 0x5eed).
std::vector<sobol_probe_entry> run_sobol_probe(gpu_context& ctx,
                                               std::vector<sobol_probe_entry> entries);

// Runs hit_probe.comp: fills `t` and `hit` of each entry with the shared hit_sphere.
std::vector<hit_probe_entry> run_hit_probe(gpu_context& ctx, std::vector<hit_probe_entry> entries);

// Runs kernel_probe.comp: fills the outputs of each entry with the shared kernels' answers
// (run_kernel_probe in kernel_probe.h).
std::vector<kernel_probe_entry> run_kernel_probe(gpu_context& ctx,
                                                 std::vector<kernel_probe_entry> entries);

// Runs light_probe.comp: fills the outputs of each entry with pdf.h's densities and samplers
// (run_light_probe in light_probe.h).
std::vector<light_probe_entry> run_light_probe(gpu_context& ctx,
                                               std::vector<light_probe_entry> entries);

// Runs pbr_probe.comp: fills the outputs of each entry with pbr.h's sample, evaluation and
// density (run_pbr_probe in pbr_probe.h).
std::vector<pbr_probe_entry> run_pbr_probe(gpu_context& ctx, std::vector<pbr_probe_entry> entries);
// Runs environment_probe.comp on a map's RGBE texels and sampling table (environment.h): fills
// each entry's outputs (run_environment_probe in environment_probe.h).
std::vector<environment_probe_entry> run_environment_probe(
    gpu_context& ctx, const std::vector<std::uint32_t>& texels, const std::vector<float>& table,
    std::vector<environment_probe_entry> entries);

// Runs light_tree_probe.comp over `lamps` and `nodes` (at RTVK_BINDING_LIGHTS and
// RTVK_BINDING_LIGHT_TREE, as gpu_scene binds them): fills the outputs of each entry with
// light_tree.h's answers (run_light_tree_probe in light_tree_probe.h).
std::vector<light_tree_probe_entry> run_light_tree_probe(
    gpu_context& ctx, const std::vector<gpu_light>& lamps, const std::vector<gpu_light_node>& nodes,
    std::vector<light_tree_probe_entry> entries);

// Runs punctual_probe.comp over `lights` (at RTVK_BINDING_PUNCTUAL, as gpu_scene binds them):
// fills the outputs of each entry with punctual.h's answers (run_punctual_probe in
// punctual_probe.h).
std::vector<punctual_probe_entry> run_punctual_probe(gpu_context& ctx,
                                                     const std::vector<gpu_punctual>& lights,
                                                     std::vector<punctual_probe_entry> entries);

// Runs world_probe.comp over the scene's spheres (through the BVH, or every sphere in turn): fills
// `t`, `hit`, `normal` and `material` of each entry with what hit_world finds along its ray.
std::vector<world_probe_entry> run_world_probe(gpu_context& ctx, const scene& s, bool use_bvh,
                                               std::vector<world_probe_entry> entries);

}  // namespace rtvk::gpu
