// The punctual lights (punctual.h reads `punctuals`), as gpu_scene::appearance_bindings binds
// them at RTVK_BINDING_PUNCTUAL: one unused element with count 0 when the scene has none. A
// shader that samples them includes this before punctual.h (the tests' punctual_probe.comp; the
// render shaders once next-event estimation lights with them).
#ifndef RTVK_PUNCTUAL_BUFFERS_GLSL
#define RTVK_PUNCTUAL_BUFFERS_GLSL
#include "lights_types.h"

layout(std430, set = 0, binding = RTVK_BINDING_PUNCTUAL) readonly buffer punctual_block {
  gpu_punctual punctuals[];
};

#endif
