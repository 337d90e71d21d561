// The structs of the tests' probe shaders (this folder; probe.h runs them). Test code only:
// the rtvk executable carries none of it (Architecture.TheRtvkBinaryCarriesNoTestProbes).
#ifndef RTVK_PROBE_TYPES_H
#define RTVK_PROBE_TYPES_H

#include "appearance_types.h"
#include "bindings.h"
#include "glsl_types.h"

// Each probe's pipeline is the scene's bindings (world_probe.comp reads the scene's buffers,
// probe.comp the camera) and its one buffer of entries, past the scene's list.
#define RTVK_BINDING_PROBE RTVK_SCENE_BINDINGS_END  // storage buffer: the probe's entries

#define RTVK_PROBE_POINTS 5  // (u, v) pairs probe.comp turns into rays
// The kernel probe's to_fixed scale and limit: a render's, F = 42 (sample_sum.h).
#define RTVK_PROBE_SUM_SCALE 4398046511104.0  // 2^42
#define RTVK_PROBE_SAMPLE_LIMIT 8589934592.0  // 2^33

RTVK_GPU_TYPES_BEGIN

// std430, read and written by probe.comp: the host fills uv, the shader fills the rest.
struct probe_io {
  vec4 uv[RTVK_PROBE_POINTS];          // xy: normalized image coordinates; zw: lens sample
  vec4 direction[RTVK_PROBE_POINTS];   // xyz: get_ray(uv).direction
  vec4 ray_origin[RTVK_PROBE_POINTS];  // xyz: get_ray(uv).origin
};
#ifdef __cplusplus
static_assert(offsetof(probe_io, direction) == 16 * RTVK_PROBE_POINTS);
static_assert(offsetof(probe_io, ray_origin) == 32 * RTVK_PROBE_POINTS);
static_assert(sizeof(probe_io) == 48 * RTVK_PROBE_POINTS);
#endif

// std430 array element for rng_probe.comp: the host fills the counters, the shader the results.
struct rng_probe_entry {
  uint pixel;         // counter: pixel index
  uint sample_index;  // counter: sample index
  uint bounce;        // counter: bounce
  uint dim;           // counter: dimension
  uint bits;          // random_bits(seed 0x5eed, ...)
  float value;        // random_float(seed 0x5eed, ...)
  float turn_cos;     // turn_cos_sin(value).x: cos(2 pi value)
  float turn_sin;     // turn_cos_sin(value).y: sin(2 pi value)
};
#ifdef __cplusplus
static_assert(offsetof(rng_probe_entry, bits) == 16);
static_assert(offsetof(rng_probe_entry, value) == 20);
static_assert(sizeof(rng_probe_entry) == 32);
#endif

// std430 array element for sobol_probe.comp: the host fills the counters, the shader the
// low-discrepancy numbers of the stream at_bounce(pixel_sample_stream(0x5eed, pixel, sample),
// bounce) (sobol.h).
struct sobol_probe_entry {
  uint pixel;         // counter: pixel index
  uint sample_index;  // counter: sample index
  uint bounce;        // counter: bounce
  uint dim;           // counter: dimension (the pair's first)
  uint bits;          // sobol_bits(s, dim)
  uint bits_x;        // sobol_bits2(s, dim).x
  uint bits_y;        // sobol_bits2(s, dim).y
  float value;        // sobol_rnd(s, dim)
  float value_x;      // sobol_rnd2(s, dim).x
  float value_y;      // sobol_rnd2(s, dim).y
};
#ifdef __cplusplus
static_assert(offsetof(sobol_probe_entry, bits) == 16);
static_assert(offsetof(sobol_probe_entry, value_y) == 36);
static_assert(sizeof(sobol_probe_entry) == 40);
#endif

// std430 array element for hit_probe.comp: the host fills a ray, an interval and a sphere; the
// shader runs hit_sphere on them.
struct hit_probe_entry {
  vec3 origin;     // ray origin, scene units
  float t_min;     // interval start
  vec3 direction;  // ray direction (may be degenerate: that is what the probe is for)
  float t_max;     // interval end
  vec3 center;     // sphere center, scene units
  float radius;    // sphere radius, scene units
  float t;         // out: the root hit_sphere found (0 when none)
  uint hit;        // out: 1 when hit_sphere reported a hit
  uint pad0;       // unused
  uint pad1;       // unused
};
#ifdef __cplusplus
static_assert(offsetof(hit_probe_entry, t_min) == 12);
static_assert(offsetof(hit_probe_entry, direction) == 16);
static_assert(offsetof(hit_probe_entry, t_max) == 28);
static_assert(offsetof(hit_probe_entry, center) == 32);
static_assert(offsetof(hit_probe_entry, radius) == 44);
static_assert(offsetof(hit_probe_entry, t) == 48);
static_assert(offsetof(hit_probe_entry, hit) == 52);
static_assert(sizeof(hit_probe_entry) == 64);
#endif

// std430 array element for world_probe.comp: the host fills a ray, the shader what hit_world
// finds along it in [0.001, max float].
struct world_probe_entry {
  vec3 origin;      // in: ray origin, scene units
  float t;          // out: the closest hit's t (0 when none)
  vec3 direction;   // in: ray direction
  uint hit;         // out: 1 when something was hit
  vec3 normal;      // out: the hit's normal, facing against the ray
  uint material;    // out: the hit sphere's material index
  uint iterations;  // out: loop trips the search took
  uint pad0;        // unused
  uint pad1;        // unused
  uint pad2;        // unused
  vec4 tangent;     // out: the hit's tangent (hit_record::tangent; 0 where none)
  vec3 texel;       // in: a normal map's texel (linear RGB) for normal_mapped at the hit
  float scale;      // in: its normalTexture.scale
  vec3 mapped;      // out: normal_mapped(hit, texel, scale, -unit direction)
  uint pad3;        // unused
};
#ifdef __cplusplus
static_assert(offsetof(world_probe_entry, tangent) == 64);
static_assert(offsetof(world_probe_entry, texel) == 80);
static_assert(offsetof(world_probe_entry, scale) == 92);
static_assert(offsetof(world_probe_entry, mapped) == 96);
static_assert(sizeof(world_probe_entry) == 112);
static_assert(offsetof(world_probe_entry, t) == 12);
static_assert(offsetof(world_probe_entry, direction) == 16);
static_assert(offsetof(world_probe_entry, hit) == 28);
static_assert(offsetof(world_probe_entry, normal) == 32);
static_assert(offsetof(world_probe_entry, material) == 44);
static_assert(offsetof(world_probe_entry, iterations) == 48);
#endif

// std430 array element for kernel_probe.comp (kernel_probe.h): the host fills a hit, the ray
// arriving at it, a material and a random stream; the shader runs the shared kernels on them.
struct kernel_probe_entry {
  vec3 p;              // in: the hit point, scene units
  float offset;        // in: hit_record::offset
  vec3 normal;         // in: unit normal, facing against the ray
  uint front_face;     // in: 1 when the ray arrived from outside
  vec3 direction;      // in: the arriving ray's direction
  uint type;           // in: RTVK_MATERIAL_*
  vec3 albedo;         // in: the material's albedo
  float fuzz;          // in: metal's fuzz
  float ir;            // in: dielectric's index of refraction
  uint key;            // in: the random stream's key
  uint bounce;         // in: the random stream's bounce
  uint scattered;      // out: 1 when scatter scattered
  vec3 attenuation;    // out: scatter's attenuation
  float disk_x;        // out: random_in_unit_disk(rnd 0, rnd 1).x
  vec3 origin_out;     // out: the scattered ray's origin
  float disk_y;        // out: and .y
  vec3 direction_out;  // out: the scattered ray's direction
  float sample_value;  // in: a sample's channel for to_fixed (fixed_sum.h)
  vec3 sky;            // out: sky_color(direction, the book's white and blue)
  uint fixed_low;      // out: to_fixed(sample_value, RTVK_PROBE_SUM_SCALE), low word
  vec3 ball;           // out: random_in_unit_sphere(rnd 0, rnd 1, rnd 2)
  uint fixed_high;     // out: and its high word
  uint fixed_top;      // out: and its top word
  uint overflows;      // out: 1 when sum_overflows(sample_value, RTVK_PROBE_SAMPLE_LIMIT)
  uint pad0;           // unused
  uint pad1;           // unused
};
#ifdef __cplusplus
static_assert(offsetof(kernel_probe_entry, offset) == 12);
static_assert(offsetof(kernel_probe_entry, normal) == 16);
static_assert(offsetof(kernel_probe_entry, front_face) == 28);
static_assert(offsetof(kernel_probe_entry, direction) == 32);
static_assert(offsetof(kernel_probe_entry, type) == 44);
static_assert(offsetof(kernel_probe_entry, albedo) == 48);
static_assert(offsetof(kernel_probe_entry, fuzz) == 60);
static_assert(offsetof(kernel_probe_entry, ir) == 64);
static_assert(offsetof(kernel_probe_entry, key) == 68);
static_assert(offsetof(kernel_probe_entry, bounce) == 72);
static_assert(offsetof(kernel_probe_entry, scattered) == 76);
static_assert(offsetof(kernel_probe_entry, attenuation) == 80);
static_assert(offsetof(kernel_probe_entry, disk_x) == 92);
static_assert(offsetof(kernel_probe_entry, origin_out) == 96);
static_assert(offsetof(kernel_probe_entry, disk_y) == 108);
static_assert(offsetof(kernel_probe_entry, direction_out) == 112);
static_assert(offsetof(kernel_probe_entry, sample_value) == 124);
static_assert(offsetof(kernel_probe_entry, sky) == 128);
static_assert(offsetof(kernel_probe_entry, fixed_low) == 140);
static_assert(offsetof(kernel_probe_entry, ball) == 144);
static_assert(offsetof(kernel_probe_entry, fixed_high) == 156);
static_assert(offsetof(kernel_probe_entry, fixed_top) == 160);
static_assert(offsetof(kernel_probe_entry, overflows) == 164);
static_assert(sizeof(kernel_probe_entry) == 176);
#endif

// std430 array element for light_probe.comp (light_probe.h): pdf.h's densities toward one light
// and the cosine density, at a point the host picks, with the host's random numbers.
struct light_probe_entry {
  gpu_light light;      // in: the light
  vec3 origin;          // in: where the directions start, scene units
  float time;           // in: the ray's instant (a sphere light moves)
  vec3 direction;       // in: a direction whose densities are asked
  float r1;             // in: the first random number of the samplers
  vec3 normal;          // in: the cosine density's unit normal
  float r2;             // in: the second
  vec3 sampled;         // out: light_random(light, origin, time, r1, r2)
  float pdf;            // out: light_pdf(light, origin, direction, time)
  vec3 cosine_sampled;  // out: cosine_random(normal, r1, r2)
  float cosine;         // out: cosine_pdf(normal, direction)
  float sampled_pdf;    // out: light_pdf of `sampled`
  uint pad0;            // unused
  uint pad1;            // unused
  uint pad2;            // unused
};
#ifdef __cplusplus
static_assert(offsetof(light_probe_entry, origin) == 96);
static_assert(offsetof(light_probe_entry, time) == 108);
static_assert(offsetof(light_probe_entry, direction) == 112);
static_assert(offsetof(light_probe_entry, r1) == 124);
static_assert(offsetof(light_probe_entry, normal) == 128);
static_assert(offsetof(light_probe_entry, r2) == 140);
static_assert(offsetof(light_probe_entry, sampled) == 144);
static_assert(offsetof(light_probe_entry, pdf) == 156);
static_assert(offsetof(light_probe_entry, cosine_sampled) == 160);
static_assert(offsetof(light_probe_entry, cosine) == 172);
static_assert(offsetof(light_probe_entry, sampled_pdf) == 176);
static_assert(sizeof(light_probe_entry) == 192);
#endif

// std430 array element for pbr_probe.comp (pbr_probe.h): a pbr_surface (shaders/shared/pbr/pbr.h),
// an outgoing direction and three uniform numbers; the shader samples pbr_sample with them and asks
// pbr_eval and pbr_pdf of the sampled direction and of a direction the host names.
struct pbr_probe_entry {
  vec3 base_color;            // in: pbr_surface::base_color, linear
  float metallic;             // in: 0 to 1
  vec3 specular_color;        // in: linear
  float roughness;            // in: perceptual
  vec3 clearcoat_normal;      // in: unit, in the shading frame
  float eta;                  // in: below over above, as the ray sees it
  vec3 sheen_color;           // in: linear
  float specular;             // in: 0 to 1
  float transmission;         // in: 0 to 1
  uint thin;                  // in: 1 thin-walled
  float clearcoat;            // in: 0 to 1
  float clearcoat_roughness;  // in: perceptual
  float sheen_roughness;      // in: perceptual
  uint sampled;               // out: 1 when pbr_sample returned a direction
  uint delta;                 // out: 1 when it came from a delta lobe
  float pdf;                  // out: pbr_sample's pdf
  vec3 wo;                    // in: the outgoing direction, unit, wo.z > 0
  float pdf_query;            // out: pbr_pdf(wo, wi_query)
  vec3 u;                     // in: pbr_sample's uniform numbers in [0, 1)
  float pdf_sampled;          // out: pbr_pdf(wo, wi)
  vec3 wi_query;              // in: a unit direction whose eval and pdf are asked
  uint pad0;                  // unused
  vec3 wi;                    // out: pbr_sample's direction
  uint pad1;                  // unused
  vec3 weight;                // out: pbr_sample's weight
  uint pad2;                  // unused
  vec3 eval_query;            // out: pbr_eval(wo, wi_query)
  uint pad3;                  // unused
  vec3 eval_sampled;          // out: pbr_eval(wo, wi)
  uint pad4;                  // unused
};
#ifdef __cplusplus
static_assert(offsetof(pbr_probe_entry, specular_color) == 16);
static_assert(offsetof(pbr_probe_entry, clearcoat_normal) == 32);
static_assert(offsetof(pbr_probe_entry, sheen_color) == 48);
static_assert(offsetof(pbr_probe_entry, specular) == 60);
static_assert(offsetof(pbr_probe_entry, transmission) == 64);
static_assert(offsetof(pbr_probe_entry, sheen_roughness) == 80);
static_assert(offsetof(pbr_probe_entry, pdf) == 92);
static_assert(offsetof(pbr_probe_entry, wo) == 96);
static_assert(offsetof(pbr_probe_entry, u) == 112);
static_assert(offsetof(pbr_probe_entry, wi_query) == 128);
static_assert(offsetof(pbr_probe_entry, wi) == 144);
static_assert(offsetof(pbr_probe_entry, weight) == 160);
static_assert(offsetof(pbr_probe_entry, eval_query) == 176);
static_assert(offsetof(pbr_probe_entry, eval_sampled) == 192);
static_assert(sizeof(pbr_probe_entry) == 208);
#endif

// std430 array element for punctual_probe.comp (punctual_probe.h): a shading point, a light and
// two uniform numbers for punctual_sample, and a direction whose sun radiance and density are
// asked.
#ifdef __cplusplus
using vec2 = glm::vec2;  // GLSL's built-in
#endif
struct punctual_probe_entry {
  vec3 p;             // in: the shading point
  uint light;         // in: which punctual light
  vec3 query;         // in: a direction for sun_radiance and sun_pdf
  uint count;         // out: punctual_count
  vec2 u;             // in: punctual_sample's uniform numbers in [0, 1)
  float distance;     // out: light_sample::distance
  float pdf;          // out: light_sample::pdf
  vec3 wi;            // out: light_sample::wi
  uint delta;         // out: 1 when light_sample::delta
  vec3 radiance;      // out: light_sample::radiance
  float sun_pdf;      // out: sun_pdf(light, query)
  vec3 sun_radiance;  // out: sun_radiance(query)
  uint pad0;          // unused
};
#ifdef __cplusplus
static_assert(offsetof(punctual_probe_entry, query) == 16);
static_assert(offsetof(punctual_probe_entry, count) == 28);
static_assert(offsetof(punctual_probe_entry, u) == 32);
static_assert(offsetof(punctual_probe_entry, distance) == 40);
static_assert(offsetof(punctual_probe_entry, pdf) == 44);
static_assert(offsetof(punctual_probe_entry, wi) == 48);
static_assert(offsetof(punctual_probe_entry, delta) == 60);
static_assert(offsetof(punctual_probe_entry, radiance) == 64);
static_assert(offsetof(punctual_probe_entry, sun_pdf) == 76);
static_assert(offsetof(punctual_probe_entry, sun_radiance) == 80);
static_assert(sizeof(punctual_probe_entry) == 96);
#endif

// std430 array element for light_tree_probe.comp (light_tree_probe.h): a shading point, its
// normal and a uniform number for light_tree_draw, and a ray (from p along d to t_hit) for the
// point query; the lamp drawn with its probability, and the leaf found with its trail's.
struct light_tree_probe_entry {
  vec3 p;          // in: the shading point
  float u;         // in: light_tree_draw's number in [0, 1)
  vec3 n;          // in: its unit normal, or zero
  float t_hit;     // in: where the ray along d hit a lamp
  vec3 d;          // in: the ray's unit direction from p
  uint lamp;       // out: the lamp drawn
  float pmf;       // out: its probability
  uint found;      // out: 1 where light_tree_find found a leaf
  uint leaf;       // out: that leaf
  float leaf_pmf;  // out: light_tree_trail_pmf of its trail from (p, n)
};
#ifdef __cplusplus
static_assert(offsetof(light_tree_probe_entry, u) == 12);
static_assert(offsetof(light_tree_probe_entry, n) == 16);
static_assert(offsetof(light_tree_probe_entry, t_hit) == 28);
static_assert(offsetof(light_tree_probe_entry, d) == 32);
static_assert(offsetof(light_tree_probe_entry, lamp) == 44);
static_assert(offsetof(light_tree_probe_entry, pmf) == 48);
static_assert(offsetof(light_tree_probe_entry, found) == 52);
static_assert(offsetof(light_tree_probe_entry, leaf) == 56);
static_assert(offsetof(light_tree_probe_entry, leaf_pmf) == 60);
static_assert(sizeof(light_tree_probe_entry) == 64);
#endif

// std430 array element for environment_probe.comp (environment_probe.h): a query direction and
// two uniform numbers in; environment.h's radiance and density of the query, and its sample from
// the numbers with the density of its direction, out.
struct environment_probe_entry {
  vec3 query;           // in: a direction whose radiance and density are asked
  float pdf_query;      // out: environment_pdf(query)
  vec3 radiance_query;  // out: environment_radiance(query)
  float pdf;            // out: environment_sample(u).pdf
  vec3 wi;              // out: environment_sample(u).wi
  float pdf_sampled;    // out: environment_pdf(wi)
  vec3 radiance;        // out: environment_sample(u).radiance
  uint trips;           // out: environment_sample_trips
  float ux;             // in: the sampler's uniform numbers in [0, 1): u.x
  float uy;             // and u.y
  uint visible;         // out: environment_visible
  uint pad;             // unused
};
#ifdef __cplusplus
static_assert(offsetof(environment_probe_entry, pdf_query) == 12);
static_assert(offsetof(environment_probe_entry, radiance_query) == 16);
static_assert(offsetof(environment_probe_entry, pdf) == 28);
static_assert(offsetof(environment_probe_entry, wi) == 32);
static_assert(offsetof(environment_probe_entry, pdf_sampled) == 44);
static_assert(offsetof(environment_probe_entry, radiance) == 48);
static_assert(offsetof(environment_probe_entry, trips) == 60);
static_assert(offsetof(environment_probe_entry, ux) == 64);
static_assert(offsetof(environment_probe_entry, uy) == 68);
static_assert(offsetof(environment_probe_entry, visible) == 72);
static_assert(sizeof(environment_probe_entry) == 80);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_PROBE_TYPES_H
