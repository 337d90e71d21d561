// What the objects look like and what fills the space between them, as the GPU reads it:
// materials, textures and the noise's tables, media, and the lights lights sampling aims at
// (their buffers: render_body.glsl's materials, appearance_buffers.glsl; bindings.h). Packed by
// host/gpu/render/packing.cpp; the kernels that read them are scatter.h, texture.h, medium.h and
// pdf.h.
#ifndef RTVK_APPEARANCE_TYPES_H
#define RTVK_APPEARANCE_TYPES_H

#include "glsl_types.h"

// Material types, as rtvk::material_type.
#define RTVK_MATERIAL_NORMAL 0
#define RTVK_MATERIAL_LAMBERTIAN 1
#define RTVK_MATERIAL_METAL 2
#define RTVK_MATERIAL_DIELECTRIC 3
#define RTVK_MATERIAL_FLAT 4
#define RTVK_MATERIAL_DIFFUSE_LIGHT 5  // emits its color (any strength); no bounce
#define RTVK_MATERIAL_ISOTROPIC 6      // scatters every way alike: a medium's phase function
// glTF 2.0's metallic-roughness model and its KHR_materials_* extensions (pbr.h); its parameters
// beyond the base color are gpu_pbr[gpu_material::pbr]
#define RTVK_MATERIAL_PBR 7
// gpu_material::flags.
// diffuse_light: emits from its front side only (the third book's)
#define RTVK_MATERIAL_ONE_SIDED 1u
#define RTVK_MATERIAL_EMISSIVE 2u      // adds `emission` (times its texture) where hit
#define RTVK_MATERIAL_CULL_BACK 4u     // rays that hit its back pass through
#define RTVK_MATERIAL_ALPHA_MASK 8u    // rays pass through where alpha < alpha_cutoff
#define RTVK_MATERIAL_ALPHA_BLEND 16u  // rays pass through with probability 1 - alpha
// Any of the flags that let a ray through the surface.
#define RTVK_MATERIAL_SEE_THROUGH 28u

// What a light is (gpu_light::kind): a shape lights sampling aims directions at.
#define RTVK_LIGHT_SPHERE 0    // by the cone it fills, seen from the point (the book's)
#define RTVK_LIGHT_QUAD 1      // by area
#define RTVK_LIGHT_TRIANGLE 2  // by area
#define RTVK_MAX_LIGHTS 256    // lights one scene may sample: each scattering evaluates them all
// gpu_light::flags: what next-event estimation (nee.h) may do with the light
#define RTVK_LIGHT_EMITS 1u      // a lamp (diffuse_light): it emits `emission`; else only aimed at
#define RTVK_LIGHT_ONE_SIDED 2u  // emits from the front of its normal only (the third book's)
// its emission varies over it (a texture, vertex colors): next-event estimation leaves it to the
// paths that hit it, which then take all of its light (no weight to share)
#define RTVK_LIGHT_UNEVEN 4u

// What a material's color is (gpu_material::texture): its albedo, or one of these.
#define RTVK_NO_TEXTURE 0xffffffffu
#define RTVK_TEXTURE_CHECKER 0   // the book's spatial checker: cells of `scale` scene units
#define RTVK_TEXTURE_IMAGE 1     // an image, nearest texel at the hit's (u, v)
#define RTVK_TEXTURE_NOISE 2     // Perlin noise at scale * p, in one of the styles below
#define RTVK_NOISE_SMOOTH 0      // 0.5 * (1 + noise(scale p))
#define RTVK_NOISE_TURBULENCE 1  // turb(scale p), seven octaves
#define RTVK_NOISE_MARBLE 2      // 0.5 * (1 + sin(scale p.z + 10 turb(p))): the book's final one
#define RTVK_PERLIN_POINTS 256   // random vectors (and entries of each permutation) of the noise
// How an image texture reads coordinates outside [0, 1] (gpu_texture::style, u in bits 0-1,
// v in bits 2-3).
#define RTVK_WRAP_CLAMP 0   // the edge's texel (the book's)
#define RTVK_WRAP_REPEAT 1  // the image tiled (glTF's default)
#define RTVK_WRAP_MIRROR 2  // tiled, every other copy mirrored

// What bounds a medium (gpu_medium::shape).
#define RTVK_BOUNDARY_SPHERE 0
#define RTVK_BOUNDARY_BOX 1

RTVK_GPU_TYPES_BEGIN

// std430 array element: 64 bytes.
struct gpu_material {
  vec3 albedo;            // fraction of light kept per channel; diffuse_light: the radiance it
                          // emits
  uint type;              // RTVK_MATERIAL_*
  float fuzz;             // metal: blur radius
  float ir;               // dielectric: index of refraction
  uint texture;           // its color's texture (gpu_texture index), or RTVK_NO_TEXTURE: albedo
  uint flags;             // RTVK_MATERIAL_ONE_SIDED, _EMISSIVE, _CULL_BACK, _ALPHA_*, or 0
  vec3 emission;          // radiance emitted besides what it reflects (with _EMISSIVE)
  uint emission_texture;  // multiplies emission (gpu_texture index), or RTVK_NO_TEXTURE
  float opacity;          // base alpha, 0 to 1 (with _ALPHA_*)
  float alpha_cutoff;     // _ALPHA_MASK: a hit counts where the alpha is at least this
  uint pbr;               // RTVK_MATERIAL_PBR: its parameters, an index into gpu_pbr[]
  uint pad1;              // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_material, albedo) == 0);
static_assert(offsetof(gpu_material, type) == 12);
static_assert(offsetof(gpu_material, fuzz) == 16);
static_assert(offsetof(gpu_material, ir) == 20);
static_assert(offsetof(gpu_material, texture) == 24);
static_assert(offsetof(gpu_material, flags) == 28);
static_assert(offsetof(gpu_material, emission) == 32);
static_assert(offsetof(gpu_material, emission_texture) == 44);
static_assert(offsetof(gpu_material, opacity) == 48);
static_assert(offsetof(gpu_material, alpha_cutoff) == 52);
static_assert(offsetof(gpu_material, pbr) == 56);
static_assert(offsetof(gpu_material, pad1) == 60);
static_assert(sizeof(gpu_material) == 64);
#endif

// std430 array element: a PBR material's parameters beyond gpu_material's (whose albedo and
// texture are its base color and base color texture, whose emission, alpha and flags serve it as
// any material), 128 bytes. Each texture is a gpu_texture index or RTVK_NO_TEXTURE; the channel it
// reads is glTF's, and it multiplies its factor. host/scene/pbr_material.h holds the meanings.
struct gpu_pbr {
  vec3 specular_color;               // KHR_materials_specular: F0 tint of the dielectric, linear
  float metallic;                    // 0 dielectric to 1 metal
  vec3 sheen_color;                  // KHR_materials_sheen: linear; 0: no sheen
  float roughness;                   // perceptual roughness, 0 to 1 (GGX alpha = roughness^2)
  vec3 attenuation_color;            // KHR_materials_volume: color white light has after
                                     // attenuation_distance inside, linear
  float attenuation_distance;        // scene units; 0 stands for infinity (no attenuation)
  float ior;                         // KHR_materials_ior: index of refraction, 1.5
  float specular;                    // KHR_materials_specular: strength, 1
  float transmission;                // KHR_materials_transmission: 0 to 1
  float thickness;                   // KHR_materials_volume: 0 thin-walled, else a closed volume
  float clearcoat;                   // KHR_materials_clearcoat: 0 to 1
  float clearcoat_roughness;         // perceptual, 0 to 1
  float sheen_roughness;             // perceptual, 0 to 1
  float normal_scale;                // the normal map's xy scale
  uint metallic_roughness_texture;   // G: roughness, B: metallic
  uint normal_texture;               // tangent-space normal map, linear
  uint specular_texture;             // A: specular
  uint specular_color_texture;       // RGB: specular_color (sRGB)
  uint transmission_texture;         // R: transmission
  uint thickness_texture;            // G: thickness
  uint clearcoat_texture;            // R: clearcoat
  uint clearcoat_roughness_texture;  // G: clearcoat_roughness
  uint clearcoat_normal_texture;     // the coat's normal map
  uint sheen_color_texture;          // RGB: sheen_color (sRGB)
  uint sheen_roughness_texture;      // A: sheen_roughness
  float clearcoat_normal_scale;      // the coat's normal map's xy scale
};
#ifdef __cplusplus
static_assert(offsetof(gpu_pbr, metallic) == 12);
static_assert(offsetof(gpu_pbr, sheen_color) == 16);
static_assert(offsetof(gpu_pbr, roughness) == 28);
static_assert(offsetof(gpu_pbr, attenuation_color) == 32);
static_assert(offsetof(gpu_pbr, attenuation_distance) == 44);
static_assert(offsetof(gpu_pbr, ior) == 48);
static_assert(offsetof(gpu_pbr, specular) == 52);
static_assert(offsetof(gpu_pbr, transmission) == 56);
static_assert(offsetof(gpu_pbr, thickness) == 60);
static_assert(offsetof(gpu_pbr, clearcoat) == 64);
static_assert(offsetof(gpu_pbr, clearcoat_roughness) == 68);
static_assert(offsetof(gpu_pbr, sheen_roughness) == 72);
static_assert(offsetof(gpu_pbr, normal_scale) == 76);
static_assert(offsetof(gpu_pbr, metallic_roughness_texture) == 80);
static_assert(offsetof(gpu_pbr, normal_texture) == 84);
static_assert(offsetof(gpu_pbr, specular_texture) == 88);
static_assert(offsetof(gpu_pbr, specular_color_texture) == 92);
static_assert(offsetof(gpu_pbr, transmission_texture) == 96);
static_assert(offsetof(gpu_pbr, thickness_texture) == 100);
static_assert(offsetof(gpu_pbr, clearcoat_texture) == 104);
static_assert(offsetof(gpu_pbr, clearcoat_roughness_texture) == 108);
static_assert(offsetof(gpu_pbr, clearcoat_normal_texture) == 112);
static_assert(offsetof(gpu_pbr, sheen_color_texture) == 116);
static_assert(offsetof(gpu_pbr, sheen_roughness_texture) == 120);
static_assert(offsetof(gpu_pbr, clearcoat_normal_scale) == 124);
static_assert(sizeof(gpu_pbr) == 128);
#endif

// std430 array element: one texture, 48 bytes (shaders/shared/texture.h reads it).
struct gpu_texture {
  vec3 even;    // checker: the color of even cells; noise: the color noise 1 has; image: a
                // tint its texels are multiplied by
  uint type;    // RTVK_TEXTURE_*
  vec3 odd;     // checker: the color of odd cells
  float scale;  // checker: a cell's size, scene units; noise: frequency, per scene unit
  uint first;   // image: its first texel in the texel array
  uint width;   // image: texels across
  uint height;  // image: rows of texels
  uint style;   // noise: RTVK_NOISE_*; image: RTVK_WRAP_* of u | that of v << 2
};
#ifdef __cplusplus
static_assert(offsetof(gpu_texture, type) == 12);
static_assert(offsetof(gpu_texture, odd) == 16);
static_assert(offsetof(gpu_texture, scale) == 28);
static_assert(offsetof(gpu_texture, first) == 32);
static_assert(offsetof(gpu_texture, width) == 36);
static_assert(offsetof(gpu_texture, height) == 40);
static_assert(offsetof(gpu_texture, style) == 44);
static_assert(sizeof(gpu_texture) == 48);
#endif

// std430: the noise's tables, made from the scene's noise seed on the host (host/scene/perlin.h).
struct gpu_perlin {
  vec4 vectors[RTVK_PERLIN_POINTS];   // xyz: random unit vectors at the lattice points
  uint perm[3 * RTVK_PERLIN_POINTS];  // permutations of 0..255 for x, y and z, one after another
};
#ifdef __cplusplus
static_assert(offsetof(gpu_perlin, perm) == 16 * RTVK_PERLIN_POINTS);
static_assert(sizeof(gpu_perlin) == 28 * RTVK_PERLIN_POINTS);
#endif

// std430 array element: a shape lights sampling aims at, 96 bytes (shaders/shared/pdf.h). The
// geometry is the scene's object's, copied: a sphere's center moves with its velocity. The lamps
// come first (RTVK_LIGHT_EMITS): next-event estimation samples those only.
struct gpu_light {
  vec3 a;         // sphere: center at time 0; quad: the corner Q; triangle: vertex 0 (scene units)
  uint kind;      // RTVK_LIGHT_*
  vec3 u;         // sphere: velocity (units per second); quad: edge u; triangle: edge to vertex 1
  float radius;   // sphere: radius (scene units)
  vec3 v;         // quad: edge v; triangle: edge to vertex 2
  float area;     // quad, triangle: area (square scene units)
  vec3 normal;    // quad, triangle: unit normal, cross(u, v) normalized
  uint flags;     // RTVK_LIGHT_EMITS, _ONE_SIDED, _UNEVEN
  vec3 emission;  // a lamp's emitted radiance (its material's color), linear RGB
  // Next-event estimation's choice among the lamps, by power (Vose's alias table): lamp k is
  // drawn with probability `pmf`; a draw u * count that lands in slot k keeps k where its
  // fraction is below `alias_q`, else takes lamp `alias`.
  float pmf;      // the probability of drawing this lamp, 0 to 1
  float alias_q;  // the share of slot k that keeps k, 0 to 1
  uint alias;     // the lamp that takes the rest of slot k
  uint pad0;      // unused
  uint pad1;      // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_light, kind) == 12);
static_assert(offsetof(gpu_light, u) == 16);
static_assert(offsetof(gpu_light, radius) == 28);
static_assert(offsetof(gpu_light, v) == 32);
static_assert(offsetof(gpu_light, area) == 44);
static_assert(offsetof(gpu_light, normal) == 48);
static_assert(offsetof(gpu_light, flags) == 60);
static_assert(offsetof(gpu_light, emission) == 64);
static_assert(offsetof(gpu_light, pmf) == 76);
static_assert(offsetof(gpu_light, alias_q) == 80);
static_assert(offsetof(gpu_light, alias) == 84);
static_assert(sizeof(gpu_light) == 96);
#endif

// std430 array element: a constant-density medium (the book's constant_medium), 96 bytes.
// Its boundary is in its own space: a point p of the scene is (dot(to_local_x.xyz, p) +
// to_local_x.w, ...) there, and a direction without the w.
struct gpu_medium {
  vec4 to_local_x;        // first row of the inverse placement, translation in w
  vec4 to_local_y;        // second row
  vec4 to_local_z;        // third row
  vec3 lo;                // box: its minimum corner; sphere: its center (local units)
  uint shape;             // RTVK_BOUNDARY_*
  vec3 hi;                // box: its maximum corner; sphere: x is its radius
  float neg_inv_density;  // -1 / density, scene units (the scene's, not the local space's)
  uint material;          // its phase function's material (isotropic)
  uint index;             // its index among the scene's media: picks its random numbers
  uint pad0;              // unused
  uint pad1;              // unused
};
#ifdef __cplusplus
static_assert(offsetof(gpu_medium, lo) == 48);
static_assert(offsetof(gpu_medium, shape) == 60);
static_assert(offsetof(gpu_medium, hi) == 64);
static_assert(offsetof(gpu_medium, neg_inv_density) == 76);
static_assert(offsetof(gpu_medium, material) == 80);
static_assert(offsetof(gpu_medium, index) == 84);
static_assert(sizeof(gpu_medium) == 96);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_APPEARANCE_TYPES_H
