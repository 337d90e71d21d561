// Next-event estimation's light tree (light_tree.h reads `light_nodes`), as gpu_scene binds it
// at RTVK_BINDING_LIGHT_TREE: one unused element (power 0) when no lamp can be drawn. Its loops
// count their trips in light_tree_trips, which shading.glsl adds to the loop budget's count
// after each step that may descend it. Included before the kernels (shading.glsl).
#ifndef RTVK_LIGHT_TREE_BUFFERS_GLSL
#define RTVK_LIGHT_TREE_BUFFERS_GLSL
#include "lights_types.h"

layout(std430, set = 0, binding = RTVK_BINDING_LIGHT_TREE) readonly buffer light_tree_block {
  gpu_light_node light_nodes[];
};

uint light_tree_trips = 0u;  // trips of the tree's loops since shading.glsl last counted them
#define LIGHT_TREE_TRIP() ++light_tree_trips

#endif
