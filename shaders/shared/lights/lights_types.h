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

// std430 array element: one node of the light tree, 64 bytes (light_tree.h descends it; host/
// scene/light_tree.cpp builds it over the lamps next-event estimation draws). Node 0 is the root;
// an interior node's first child is the next node, its second `second`. Each node bounds the
// lamps under it: where they are, which way they emit (a cone of normals widened by how far
// past them the light leaves), and their power. The array holds one unused element (power 0) when
// no lamp can be drawn.
struct gpu_light_node {
  vec3 lo;      // the lamps' bounding box, low corner (scene units)
  float power;  // their summed power (lamp_power's units); 0: nothing to draw
  vec3 hi;      // the box's high corner
  float cos_o;  // cos theta_o: the cone about `axis` holding every lamp's normal; -1: all ways
  vec3 axis;    // the cone's unit axis
  float cos_e;  // cos theta_e: how far past its normal a lamp's light leaves (0: a half space)
  uint second;  // interior: the second child's index; leaf: the trail (bit d: the second child
                // was taken at depth d)
  uint lamp;    // leaf: the lamp's index in the light table
  uint leaf;    // 1: a leaf (one lamp); 0: interior
  uint pad0;    // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_light_node, power) == 12);
static_assert(offsetof(gpu_light_node, hi) == 16);
static_assert(offsetof(gpu_light_node, cos_o) == 28);
static_assert(offsetof(gpu_light_node, axis) == 32);
static_assert(offsetof(gpu_light_node, cos_e) == 44);
static_assert(offsetof(gpu_light_node, second) == 48);
static_assert(offsetof(gpu_light_node, lamp) == 52);
static_assert(offsetof(gpu_light_node, leaf) == 56);
static_assert(sizeof(gpu_light_node) == 64);
#endif
RTVK_GPU_TYPES_END

#endif  // RTVK_LIGHTS_TYPES_H
