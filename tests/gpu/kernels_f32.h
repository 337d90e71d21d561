#pragma once
// The shared kernels (shaders/shared) compiled a second time in C++, with float as their `real`:
// the GPU's arithmetic on the host, operation for operation, so that the probe shaders' results
// can be held to it exactly where the operations are exactly rounded (+, -, *) and to a stated
// bound where the device's sqrt, division and transcendentals may differ. The compilation is its
// own translation unit (kernels_f32.cpp), since a unit compiles the kernels with one `real` only.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "camera_ubo.h"
#include "lights_types.h"
#include "probe_types.h"

namespace rtvk::f32 {

glm::vec2 turn_cos_sin(float b);

struct ray_f {
  glm::vec3 origin;     // scene units
  glm::vec3 direction;  // not normalized
};
// get_ray on the camera_ubo's vectors (what the GPU reads), in float.
ray_f get_ray(const gpu::camera_ubo& cam, float s, float t, glm::vec2 lens);

// The opencv lens's distortion and its Newton inverse (camera_rays.h) in float, as the GPU
// computes them: ka = (k1, k2, p1, p2), kb = (k3, k4, k5, k6); normalized image coordinates.
glm::vec2 opencv_distort(glm::vec4 ka, glm::vec4 kb, glm::vec2 p);
bool opencv_undistort(glm::vec4 ka, glm::vec4 kb, glm::vec2 target, float limit2, glm::vec2& p);

// hit_sphere in float: true and the root in t, or false.
bool hit_sphere(glm::vec3 center, float radius, ray_f r, float t_min, float t_max, float& t);

// record_hit at t, then scatter_origin for a ray leaving along `leaving`, in float: where the
// GPU starts the next ray.
glm::vec3 scatter_origin(glm::vec3 center, float radius, ray_f r, float t, glm::vec3 leaving);

// run_environment_probe (tests/gpu/probes/environment_probe.h) in float, on a map's RGBE texels
// and sampling table (environment.h).
void run_environment_probe(const std::uint32_t* texels, const float* table,
                           gpu::environment_probe_entry& e);

// run_kernel_probe (tests/gpu/probes/kernel_probe.h) in float: what kernel_probe.comp computes.
void run_kernel_probe(gpu::kernel_probe_entry& e);

// run_light_probe (tests/gpu/probes/light_probe.h) in float: what light_probe.comp computes.
void run_light_probe(gpu::light_probe_entry& e);

// run_pbr_probe (tests/gpu/probes/pbr_probe.h) in float: what pbr_probe.comp computes. And pbr.h's
// density and evaluation alone, on the entry's material (pbr_probe_surface), for the statistical
// statistical tests (tests/bsdf), which ask for millions of samples.
void run_pbr_probe(gpu::pbr_probe_entry& e);
bool pbr_sample(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 u, glm::vec3& wi,
                glm::vec3& weight, float& pdf, bool& delta);
float pbr_pdf(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 wi);
glm::vec3 pbr_eval(const gpu::pbr_probe_entry& e, glm::vec3 wo, glm::vec3 wi);

// run_light_tree_probe (tests/gpu/probes/light_tree_probe.h) in float over `lamps` and `nodes`:
// what light_tree_probe.comp computes.
void run_light_tree_probe(const std::vector<gpu::gpu_light>& lamps,
                          const std::vector<gpu::gpu_light_node>& nodes,
                          gpu::light_tree_probe_entry& e);

// run_punctual_probe (tests/gpu/probes/punctual_probe.h) in float over `lights` (their count
// the elements', as the shader reads it): what punctual_probe.comp computes.
void run_punctual_probe(const std::vector<gpu::gpu_punctual>& lights, gpu::punctual_probe_entry& e);

}  // namespace rtvk::f32
