// The body of the render shaders: render.comp (the compute BVH), render_query.comp (ray queries)
// and render_ray.rgen (a ray-tracing pipeline's ray generation) each set the version, extensions
// and RTVK_INVOCATION_ID (the pixel and view of the invocation) and include this.
//
// One invocation per pixel and view traces a run of that pixel's samples, from where the pixel
// stands (pixel_sum::samples) up to pc.sample_target, path after path without waiting for the
// other invocations' paths, and adds them to the pixel's exact sums in one write. The loop budget
// bounds the work one invocation does (lavapipe silently stops loops at 65,535 iterations in
// all): an invocation that runs out keeps the samples it finished and
// the next dispatch goes on from there. A sample that does not fit a whole budget leaves the pixel
// as it was and is drawn again under the larger budget the host then gives (the pacer, host/gpu/
// render/pacer.h); only one that does not fit the largest fails the render. The budget and the
// dispatch's pixels bound its work on every device, before any of it was measured. The dispatch's z index is the view: every camera (or animation frame) of a group shares
// the scene buffers and the dispatch.
#include "shared_types.h"

// The host fixes the render's switches when it builds the pipeline, so the compiler drops the
// code a render does not use instead of branching on it in every invocation.
layout(constant_id = RTVK_SPEC_JITTER) const bool jitter = false;   // random spots in the pixel
layout(constant_id = RTVK_SPEC_LENS) const bool any_lens = false;   // a view has an aperture
layout(constant_id = RTVK_SPEC_USE_BVH) const bool use_bvh = true;  // else every sphere in turn
layout(constant_id = RTVK_SPEC_COUNT_RAYS) const bool count_rays = false;  // per-pixel counts
layout(constant_id = RTVK_SPEC_LIGHTS) const bool sample_lights = false;  // the third book's
// next-event estimation (shaders/shared/lights/nee.h): a light sample and a shadow ray a vertex
layout(constant_id = RTVK_SPEC_NEE) const bool nee = false;
// a view has a calibrated lens or a rolling shutter (camera_rays.h)
layout(constant_id = RTVK_SPEC_CALIBRATED) const bool calibrated_cameras = false;

layout(std140, set = 0, binding = RTVK_BINDING_CAMERA) uniform camera_block {
  camera_ubo cams[RTVK_MAX_VIEWS];
};
layout(std430, set = 0, binding = RTVK_BINDING_MATERIALS) readonly buffer material_block {
  gpu_material materials[];
};
layout(std430, set = 0, binding = RTVK_BINDING_IMAGE) buffer image_block {
  pixel_sum sums[];
};
layout(std430, set = 0, binding = RTVK_BINDING_STATUS) buffer status_block {
  render_status status;
};
layout(push_constant) uniform push_block {
  render_push pc;
};
#include "scene_buffers.glsl"
#include "appearance_buffers.glsl"
#include "punctual_buffers.glsl"
#include "light_tree_buffers.glsl"

// Whether the scene has punctual lights: next-event estimation draws them (lights/nee.h), else
// their code is compiled out.
layout(constant_id = RTVK_SPEC_PUNCTUAL) const bool any_punctual = false;
#define NEE_PUNCTUAL_COUNT (nee && any_punctual ? punctuals[0].count : 0u)
// Whether the scene has an environment map: without, environment.h's code is compiled out and
// escaping rays see the sky as they always did; next-event estimation draws it where it has one.
layout(constant_id = RTVK_SPEC_ENVIRONMENT) const bool any_environment = false;
#define NEE_ENVIRONMENT (nee && any_environment)

// The lights scattering aims at (pdf.h's LIGHT_COUNT): none unless the pipeline samples them, so
// that plain renders compile the lights' code out; under next-event estimation, the lamps.
uint light_count() {
  return sample_lights || nee ? pc.light_count : 0u;
}

#include "camera_rays.h"
#include "fixed_sum.h"
#include "random.h"
#include "shading.glsl"

// A new path for the pixel's sample: its stream and its first ray (sample_ray, as pixel_color in
// host/cpu/render_cpu.cpp draws it). `j` counts rows from the bottom.
path_state pixel_path(camera_ubo cam, uvec2 pixel, uint j, uint sample_index) {
  random_stream s =
      pixel_sample_stream(pc.seed, pixel.y * cam.image_width + pixel.x, sample_index);
  // Next-event estimation's paths draw Sobol numbers in every dimension (random.h).
  if (nee) s = with_low_discrepancy(s);
  // Strata come with lights sampling only (pixel_strata): plain pipelines compile them out.
  ray r = sample_ray(cam, cam.image_width, cam.image_height, pixel.x, j, s, jitter, any_lens,
                     sample_lights ? pc.strata : 1u, sample_index);
  return start_path(r, s, pc.max_depth);
}

// Adds x, a 96-bit integer as (low, high, top) words, to a channel's sum: (low, high) and top.
void add_fixed(inout uvec2 sum, inout uint top, uvec3 x) {
  uint carry_low, carry_high, carry_sum;
  sum.x = uaddCarry(sum.x, x.x, carry_low);
  sum.y = uaddCarry(sum.y, x.y, carry_high);
  sum.y = uaddCarry(sum.y, carry_low, carry_sum);
  top += x.z + carry_high + carry_sum;
}

// Adds one sample's color (and its rays, when counted) to the pixel's sums; returns whether a
// channel was past the limit (sum_overflows: the render fails rather than clamp it). A sample
// with a NaN or infinite channel adds black and counts in `dropped`.
bool add_sample(inout pixel_sum acc, vec3 c, uint rays, inout uint dropped) {
  if (!sample_is_finite(c.r) || !sample_is_finite(c.g) || !sample_is_finite(c.b)) {
    ++dropped;
    c = vec3(0.0);
  }
  add_fixed(acc.r, acc.r_top, to_fixed(c.r, pc.sample_limit, pc.sum_scale));
  add_fixed(acc.g, acc.g_top, to_fixed(c.g, pc.sample_limit, pc.sum_scale));
  add_fixed(acc.b, acc.b_top, to_fixed(c.b, pc.sample_limit, pc.sum_scale));
  if (count_rays) acc.rays += rays;
  ++acc.samples;
  return sum_overflows(c.r, pc.sample_limit) || sum_overflows(c.g, pc.sample_limit) ||
         sum_overflows(c.b, pc.sample_limit);
}

// lavapipe 22.3 stops every loop of an invocation, silently, once 65,535 trips were taken in
// all -- loops rtvk does not count and, on the hardware paths, the driver's own traversal loop
// included -- and a loop cut short gives a wrong sample (a search cut short is a miss). A loop of
// pc.probe_trips (2) trips run after the invocation's work shows it: past the limit, it stops
// after its first. The body mixes the trips so no compiler can fold the loop away. On every path
// and device: a driver not known to have a limit (pacer.h) is found out by it.
bool limit_was_hit() {
  uint mixed = 0u;
  for (uint i = 0u; i < pc.probe_trips; ++i) mixed = mixed * 0x9e3779b9u + i + 1u;
  return mixed != 0x9e3779b9u + 2u;
}

void main() {
  // x from the left, y from the top of the image; the dispatch covers one band of rows of the
  // region, for every view.
  if (RTVK_INVOCATION_ID.x >= pc.region_width || RTVK_INVOCATION_ID.y >= pc.band_rows) return;
  uint view = RTVK_INVOCATION_ID.z;
  uint index = (view * pc.band_rows + pc.sums_row0 + RTVK_INVOCATION_ID.y) * pc.region_width +
               RTVK_INVOCATION_ID.x;
  pixel_sum acc = sums[index];
  if (acc.samples >= pc.sample_target) return;
  camera_ubo cam = cams[view];
  uvec2 pixel = uvec2(RTVK_INVOCATION_ID.x + pc.region_x0, RTVK_INVOCATION_ID.y + pc.band_y0);
  uint j = cam.image_height - 1u - pixel.y;  // the lesson counts rows from the bottom

  // ray_color's loop, one bounce per trip, over all the samples: a path that ends is added and
  // the next sample's path starts on the next trip, so an invocation whose path ended early does
  // not idle while the others of its SIMD group (lavapipe's 8 lanes, a warp) bounce on.
  uint first = acc.samples;
  uint iterations = 0u;
  uint rays = 0u;  // of the path in flight
  uint overflowed = 0u;  // samples past the limit
  uint dropped = 0u;     // samples not finite, or whose BVH walk overflowed its stack
  uint stack_drops = 0u;  // samples whose BVH walk overflowed its stack
  uint rays_added = 0u;  // by the samples added (when counted)
  // A calibrated lens's inverse loops too: each first ray counts its most Newton steps.
  uint lens_work = calibrated_model(cam.projection) ? RTVK_LENS_ITERATIONS + 1u : 0u;
  iterations += lens_work;
  path_state p = pixel_path(cam, pixel, j, pc.sample_begin + acc.samples);
  while (true) {
    precise vec3 c;
    bool ended = ray_color_step(p, c, iterations, rays);
    if (iterations > pc.loop_budget) break;  // the path in flight is dropped and drawn again
    if (!ended) continue;
    if (stack_overflowed) {  // the walk stopped short: dropped as a NaN sample is, and counted
      stack_overflowed = false;
      ++stack_drops;
      c = vec3(uintBitsToFloat(0x7fc00000u));
    }
    if (add_sample(acc, c, rays, dropped)) ++overflowed;
    rays_added += rays;
    rays = 0u;
    if (acc.samples >= pc.sample_target) break;
    iterations += lens_work;
    p = pixel_path(cam, pixel, j, pc.sample_begin + acc.samples);
  }
  // A driver's loop limit cut some loop short, unseen: nothing of this dispatch is kept or
  // counted, and the host holds the budget below the limit (on a device it did not know had
  // one) or counts each traced ray as more iterations (the hardware paths' traversals).
  if (limit_was_hit()) {
    atomicAdd(status.cut_traversals, 1u);
    atomicAdd(status.unfinished_pixels, 1u);
    return;
  }
  if (iterations > pc.loop_budget) {
    atomicAdd(status.unfinished_pixels, 1u);  // the host dispatches again
    if (acc.samples == first) {  // one sample needs more than a whole budget: the host gives
      atomicAdd(status.starved_pixels, 1u);  // later dispatches a larger one, or at the largest
      atomicMax(status.starved_budget, pc.loop_budget);  // fails the render rather than show this
      return;
    }
  }
  if (overflowed != 0u) atomicAdd(status.overflowed_samples, overflowed);
  if (dropped != 0u) atomicAdd(status.dropped_samples, dropped);
  if (stack_drops != 0u) atomicAdd(status.stack_overflows, stack_drops);
  if (count_rays && rays_added != 0u) {  // a 64-bit count: the carry goes to the high word
    uint before = atomicAdd(status.rays_low, rays_added);
    if (before + rays_added < before) atomicAdd(status.rays_high, 1u);
  }
  sums[index] = acc;
}
