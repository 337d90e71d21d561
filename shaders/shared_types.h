// Every struct that crosses from the host to the GPU, written once and included by both the C++
// host and the GLSL shaders. In C++ each offset is static_asserted against the std140/std430 rules,
// so host and shader cannot drift apart silently.
#ifndef RTVK_SHARED_TYPES_H
#define RTVK_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
namespace rtvk::gpu {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uint = std::uint32_t;
#endif

// Descriptor bindings, set 0.
#define RTVK_BINDING_CAMERA 0   // uniform buffer: camera_ubo
#define RTVK_BINDING_SPHERES 1  // storage buffer: gpu_sphere[]
#define RTVK_BINDING_IMAGE 2    // storage buffer: float RGB per pixel, row 0 at the top
#define RTVK_BINDING_PROBE 3    // storage buffer: probe_io (probe.comp only)

#define RTVK_PROBE_POINTS 5  // (u, v) pairs probe.comp turns into rays

// std140. Each vec3 takes a 16-byte slot; the scalar after it packs into the slot's last 4 bytes.
struct camera_ubo {
  vec3 origin;        // eye position, scene units
  uint image_width;   // pixels
  vec3 horizontal;    // full viewport width as a vector, scene units
  uint image_height;  // pixels
  vec3 vertical;      // full viewport height as a vector, scene units
  uint pad0;          // unused: keeps lower_left in its own slot
  vec3 lower_left;    // lower-left corner of the viewport, scene units
  uint pad1;          // unused: rounds the struct to 64 bytes
};

// std430 array element: 16 bytes.
struct gpu_sphere {
  vec3 center;   // scene units
  float radius;  // scene units, > 0
};

// Push constants: what changes from one dispatch to the next.
struct render_push {
  uint sphere_count;  // spheres in the storage buffer
  uint pad0;          // unused
  uint pad1;          // unused
  uint pad2;          // unused
};

// std430, read and written by probe.comp: the host fills uv, the shader fills the rest.
struct probe_io {
  vec4 uv[RTVK_PROBE_POINTS];         // xy: normalized image coordinates to probe
  vec4 direction[RTVK_PROBE_POINTS];  // xyz: get_ray(uv).direction
  vec4 ray_origin;                    // xyz: get_ray(0, 0).origin
  camera_ubo echo;                    // the uniform buffer exactly as the shader read it
};

#ifdef __cplusplus
static_assert(offsetof(camera_ubo, origin) == 0);
static_assert(offsetof(camera_ubo, image_width) == 12);
static_assert(offsetof(camera_ubo, horizontal) == 16);
static_assert(offsetof(camera_ubo, image_height) == 28);
static_assert(offsetof(camera_ubo, vertical) == 32);
static_assert(offsetof(camera_ubo, pad0) == 44);
static_assert(offsetof(camera_ubo, lower_left) == 48);
static_assert(offsetof(camera_ubo, pad1) == 60);
static_assert(sizeof(camera_ubo) == 64);
static_assert(offsetof(gpu_sphere, center) == 0);
static_assert(offsetof(gpu_sphere, radius) == 12);
static_assert(sizeof(gpu_sphere) == 16);
static_assert(sizeof(render_push) == 16 && sizeof(render_push) <= 128);
static_assert(offsetof(probe_io, uv) == 0);
static_assert(offsetof(probe_io, direction) == 16 * RTVK_PROBE_POINTS);
static_assert(offsetof(probe_io, ray_origin) == 32 * RTVK_PROBE_POINTS);
static_assert(offsetof(probe_io, echo) == 32 * RTVK_PROBE_POINTS + 16);
static_assert(sizeof(probe_io) == 32 * RTVK_PROBE_POINTS + 16 + 64);
}  // namespace rtvk::gpu
#endif

#endif  // RTVK_SHARED_TYPES_H
