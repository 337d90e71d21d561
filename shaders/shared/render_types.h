// What the passes over the scene write, and what they are told besides the scene: the render's
// push constants, each pixel's exact sums and the status the shader reports (render_body.glsl;
// host/gpu/render/render_targets.h and gpu_engine.cpp); tonemap.comp's push constants, which run
// of those sums it encodes to RGBA8; and aov.comp's records (rtvk render --aov on the device;
// host/gpu/render/aov_pass.h reads them). Their bindings: bindings.h.
#ifndef RTVK_RENDER_TYPES_H
#define RTVK_RENDER_TYPES_H

#include "glsl_types.h"

RTVK_GPU_TYPES_BEGIN

// Push constants (std430): the render's settings and what changes from one dispatch to the next.
// Each dispatch brings every pixel of the band up to `sample_target` samples of the window; an
// invocation whose loop budget runs out first keeps what it finished, and a later dispatch goes
// on from there.
struct render_push {
  vec3 sky_horizon;     // linear RGB seen along -y
  uint sphere_count;    // spheres in the storage buffer
  vec3 sky_zenith;      // linear RGB seen along +y
  uint sample_begin;    // the window's first sample index: a pixel's k-th sample is this + k
  uint seed;            // the render's random seed
  uint max_depth;       // most scatter events per path
  uint loop_budget;     // most loop iterations one invocation runs in this dispatch (pacer.h)
  uint band_y0;         // first image row of this band: the image buffers hold rows band_y0 on
  uint band_rows;       // rows in this band
  uint region_x0;       // first image column drawn
  uint region_width;    // columns drawn; the image buffers hold, per view, band_rows x this
  uint sample_target;   // samples of the window each pixel has after this dispatch
  float sum_scale;      // 2^F: a sample's channel c adds floor(c * sum_scale) (sample_sum.h)
  float sample_limit;   // largest channel value a sample may add (sum_sample_limit); past it the
                        // sample overflows and the render fails
  uint sums_row0;       // rows of the sums buffer before this band's first (0, or band_y0 when
                        // the buffer holds the whole image: the viewer's accumulation)
  uint quad_count;      // quads in the storage buffer
  uint triangle_count;  // triangles in the storage buffer
  uint instance_count;  // instances in their storage buffer
  uint medium_count;    // media in their storage buffer
  uint light_count;     // lights in their storage buffer; 0: plain sampling
  uint strata;          // the pixel is cut into strata x strata cells, each of samples 0 to
                        // strata^2 - 1 in its own (camera_rays.h); 0 or 1: not stratified
  uint trace_cost;      // loop iterations each path step counts (shading.glsl), and on the
                        // hardware paths each traced ray too, for the driver's own traversal
                        // loop (world_rt.glsl): 1, doubled after a loop limit cut an invocation
  uint probe_trips;     // 2: the trips of the loop that tells whether a driver's loop limit
                        // cut the invocation short (limit_was_hit); a push constant, not unrolled
  uint disk_count;      // disks in the storage buffer
};
#ifdef __cplusplus
static_assert(offsetof(render_push, sky_horizon) == 0);
static_assert(offsetof(render_push, sphere_count) == 12);
static_assert(offsetof(render_push, sky_zenith) == 16);
static_assert(offsetof(render_push, sample_begin) == 28);
static_assert(offsetof(render_push, seed) == 32);
static_assert(offsetof(render_push, max_depth) == 36);
static_assert(offsetof(render_push, loop_budget) == 40);
static_assert(offsetof(render_push, band_y0) == 44);
static_assert(offsetof(render_push, band_rows) == 48);
static_assert(offsetof(render_push, region_x0) == 52);
static_assert(offsetof(render_push, region_width) == 56);
static_assert(offsetof(render_push, sample_target) == 60);
static_assert(offsetof(render_push, sum_scale) == 64);
static_assert(offsetof(render_push, sample_limit) == 68);
static_assert(offsetof(render_push, sums_row0) == 72);
static_assert(offsetof(render_push, quad_count) == 76);
static_assert(offsetof(render_push, triangle_count) == 80);
static_assert(offsetof(render_push, instance_count) == 84);
static_assert(offsetof(render_push, medium_count) == 88);
static_assert(offsetof(render_push, light_count) == 92);
static_assert(offsetof(render_push, strata) == 96);
static_assert(offsetof(render_push, trace_cost) == 100);
static_assert(offsetof(render_push, probe_trips) == 104);
static_assert(offsetof(render_push, disk_count) == 108);
static_assert(sizeof(render_push) == 112 && sizeof(render_push) <= 128);
#endif

// std430 array element: one pixel's exact running sums, 48 bytes. Each channel is a 96-bit
// fixed-point number of F fractional bits (sample_sum.h): (low word, high word) and a top word.
struct pixel_sum {
  uvec2 r;       // sum of floor(red * 2^F), bits 0-63
  uvec2 g;       // green, likewise
  uvec2 b;       // blue, likewise
  uint samples;  // samples of the window added so far
  uint rays;     // rays traced for them (when counted)
  uint r_top;    // bits 64-95 of the red sum
  uint g_top;    // of the green sum
  uint b_top;    // of the blue sum
  uint pad;      // unused
};
#ifdef __cplusplus
static_assert(offsetof(pixel_sum, r) == 0);
static_assert(offsetof(pixel_sum, g) == 8);
static_assert(offsetof(pixel_sum, b) == 16);
static_assert(offsetof(pixel_sum, samples) == 24);
static_assert(offsetof(pixel_sum, rays) == 28);
static_assert(offsetof(pixel_sum, r_top) == 32);
static_assert(offsetof(pixel_sum, g_top) == 36);
static_assert(offsetof(pixel_sum, b_top) == 40);
static_assert(sizeof(pixel_sum) == 48);
#endif

// std430: written by the shader when something went wrong.
struct render_status {
  uint starved_pixels;      // invocations whose first sample alone overran loop_budget
  uint unfinished_pixels;   // invocations that stopped short of sample_target (counted per pass)
  uint starved_budget;      // the largest loop_budget under which some invocation starved
  uint overflowed_samples;  // samples with a channel past sample_limit (the render fails)
  uint dropped_samples;     // samples with a NaN or infinite channel: they add black
  uint rays_low;            // rays traced for the samples added (when counted), low word
  uint rays_high;           // and high word
  uint cut_traversals;      // invocations a driver's loop limit cut short (limit_was_hit):
                            // nothing of them is kept; the host redraws them
  uint stack_overflows;     // samples whose BVH walk would have pushed past its stack: dropped
                            // (added black, counted in dropped_samples too), never a wrong hit
};
#ifdef __cplusplus
static_assert(offsetof(render_status, unfinished_pixels) == 4);
static_assert(offsetof(render_status, starved_budget) == 8);
static_assert(offsetof(render_status, overflowed_samples) == 12);
static_assert(offsetof(render_status, dropped_samples) == 16);
static_assert(offsetof(render_status, rays_low) == 20);
static_assert(offsetof(render_status, rays_high) == 24);
static_assert(offsetof(render_status, cut_traversals) == 28);
static_assert(offsetof(render_status, stack_overflows) == 32);
static_assert(sizeof(render_status) == 36);
#endif

// Push constants of tonemap.comp (std430).
struct tonemap_push {
  uint first;            // the first pixel_sum entry to encode (and RGBA8 entry to write)
  uint pixels;           // pixel_sum entries to encode
  uint row_invocations;  // invocations in x of the whole dispatch (a tile's gl_NumWorkGroups is
                         // less)
  uint transform;        // RTVK_VIEW_* (view_transform.h): AgX is computed, the rest thresholded
  float mean_scale;      // AgX: 2^(exposure - F), a fixed-point mean's scene-linear light
};
#ifdef __cplusplus
static_assert(offsetof(tonemap_push, pixels) == 4);
static_assert(offsetof(tonemap_push, row_invocations) == 8);
static_assert(offsetof(tonemap_push, transform) == 12);
static_assert(offsetof(tonemap_push, mean_scale) == 16);
static_assert(sizeof(tonemap_push) == 20);
#endif

// std430 array element for aov.comp: what the ray through one pixel's center hits first
// (aov.h), row-major over the render window from its top row.
struct gpu_aov {
  vec3 normal;     // world-space shading normal, facing against the ray; 0 where nothing is hit
  float distance;  // along the camera ray to the hit, scene units; +inf where nothing is hit
  vec3 albedo;     // the material's color there (aov_albedo); 0 where nothing is hit
  float depth;     // z depth: along the camera's axis from its eye, scene units; +inf likewise
  uint object;     // the hit object's place in the scan order (bvh_world's key), if hit
  uint instance;   // the instance + 1 it was reached through; 0: the scene's own objects
  uint material;   // the hit's material index, if hit
  uint hit;        // 1 where something was hit
};
#ifdef __cplusplus
static_assert(offsetof(gpu_aov, normal) == 0);
static_assert(offsetof(gpu_aov, distance) == 12);
static_assert(offsetof(gpu_aov, albedo) == 16);
static_assert(offsetof(gpu_aov, depth) == 28);
static_assert(offsetof(gpu_aov, object) == 32);
static_assert(offsetof(gpu_aov, instance) == 36);
static_assert(offsetof(gpu_aov, material) == 40);
static_assert(offsetof(gpu_aov, hit) == 44);
static_assert(sizeof(gpu_aov) == 48);
#endif

RTVK_GPU_TYPES_END

#endif  // RTVK_RENDER_TYPES_H
