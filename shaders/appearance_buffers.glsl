// What shading reads besides the materials, as gpu_scene::appearance_bindings binds it: the
// textures (texture.h reads `textures`, `texels` and `perlin`), the media, the lights (pdf.h
// reads `lights`) the PBR materials' parameters (pbr_shading.h reads `pbrs`), pbr.h's tables (`bsdf_table`) and the
// environment map (environment.h). render.comp's and aov.comp's.
#ifndef RTVK_APPEARANCE_BUFFERS_GLSL
#define RTVK_APPEARANCE_BUFFERS_GLSL

layout(std430, set = 0, binding = RTVK_BINDING_TEXTURES) readonly buffer texture_block {
  gpu_texture textures[];
};
layout(std430, set = 0, binding = RTVK_BINDING_TEXELS) readonly buffer texel_block {
  uint texels[];
};
layout(std430, set = 0, binding = RTVK_BINDING_PERLIN) readonly buffer perlin_block {
  gpu_perlin perlin;
};
layout(std430, set = 0, binding = RTVK_BINDING_MEDIA) readonly buffer medium_block {
  gpu_medium media[];
};
layout(std430, set = 0, binding = RTVK_BINDING_LIGHTS) readonly buffer light_block {
  gpu_light lights[];
};
layout(std430, set = 0, binding = RTVK_BINDING_PBR) readonly buffer pbr_block {
  gpu_pbr pbrs[];
};
// pbr.h's tables (bsdf_tables.h reads them through BSDF_TABLE).
layout(std430, set = 0, binding = RTVK_BINDING_BSDF_TABLES) readonly buffer bsdf_table_block {
  float bsdf_table[];
};
// The environment map's RGBE texels and its sampling table (lights/environment.h reads them).
layout(std430, set = 0, binding = RTVK_BINDING_ENVIRONMENT) readonly buffer environment_block {
  uint environment_texels[];
};
layout(std430, set = 0, binding = RTVK_BINDING_ENVIRONMENT_CDF) readonly buffer environment_cdf_block {
  float environment_table[];
};

#endif
