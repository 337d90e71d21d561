// The punctual lights as the GPU reads them (RTVK_BINDING_PUNCTUAL; punctual.h samples them):
// point, spot and directional lights, a directional one with a size being a sun. Packed by
// host/gpu/scene/packing.cpp (to_gpu_punctuals) from the scene's punctual_light list
// (scene.h; light_sources.h makes the records; docs/lighting.md has the units).
#ifndef RTVK_LIGHTS_TYPES_H
#define RTVK_LIGHTS_TYPES_H

#include "glsl_types.h"

// What a punctual light is (gpu_punctual::kind).
#define RTVK_PUNCTUAL_POINT 0u  // every way alike from `position`
#define RTVK_PUNCTUAL_SPOT 1u   // from `position`, in a cone about `direction`
#define RTVK_PUNCTUAL_DIRECTIONAL \
  2u  // from infinitely far, along `direction` (a sun: cone_gap > 0)

RTVK_GPU_TYPES_BEGIN
// std430 array element: one punctual light, 64 bytes. The array holds one unused element (count
// 0) when the scene has none: a buffer cannot be empty.
struct gpu_punctual {
  vec3 position;       // point, spot: where it stands, scene units
  uint kind;           // RTVK_PUNCTUAL_*
  vec3 direction;      // spot, directional: unit, the way its light travels (glTF's -Z)
  float angle_scale;   // spot: 1 / max(0.001, cos(inner) - cos(outer)) (KHR_lights_punctual)
  vec3 intensity;      // color * intensity: point, spot: candela; directional: lux (per channel)
  float angle_offset;  // spot: -cos(outer) * angle_scale
  float cone_gap;      // directional: 1 - cos of half the angular diameter; 0: a delta light
  uint count;          // the lights in the array, the same in every element (0: none)
  float pad0;
  float pad1;
};
#ifdef __cplusplus
static_assert(offsetof(gpu_punctual, kind) == 12);
static_assert(offsetof(gpu_punctual, direction) == 16);
static_assert(offsetof(gpu_punctual, angle_scale) == 28);
static_assert(offsetof(gpu_punctual, intensity) == 32);
static_assert(offsetof(gpu_punctual, angle_offset) == 44);
static_assert(offsetof(gpu_punctual, cone_gap) == 48);
static_assert(offsetof(gpu_punctual, count) == 52);
static_assert(sizeof(gpu_punctual) == 64);
#endif
RTVK_GPU_TYPES_END

#endif  // RTVK_LIGHTS_TYPES_H
