// The body of the kernel probe, itself in the kernels' language: the probe shader
// (kernel_probe.comp) and the tests' float compilation (tests/gpu/kernels_f32.cpp) run this same
// function on the same entries, so whatever they disagree on is the device's arithmetic.
#ifndef RTVK_KERNEL_PROBE_H
#define RTVK_KERNEL_PROBE_H
#include "fixed_sum.h"
#include "kernel_lang.h"
#include "probe_types.h"
#include "random.h"
#include "ray.h"
#include "ray_color.h"
#include "scatter.h"
#include "shared_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::kernel_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

inline void run_kernel_probe(INOUT(kernel_probe_entry) e) {
  hit_record rec;
  rec.p = e.p;
  rec.normal = e.normal;
  rec.t = real(1.0);
  rec.front_face = e.front_face != 0u;
  rec.material = 0u;
  rec.offset = e.offset;
  random_stream s = random_stream(e.key, e.bounce, 0u, 0u, false);
  ray r_in = ray(e.p - e.direction, e.direction, real(0.0));
  precise real3 attenuation;
  precise ray scattered;
  e.scattered =
      scatter(e.type, e.albedo, e.fuzz, e.ir, r_in, rec, s, attenuation, scattered) ? 1u : 0u;
  e.attenuation = attenuation;
  e.origin_out = scattered.origin;
  e.direction_out = scattered.direction;
  e.sky = sky_color(e.direction, real3(1.0, 1.0, 1.0), real3(0.5, 0.7, 1.0));
  e.ball = random_in_unit_sphere(real(rnd(s, 0u)), real(rnd(s, 1u)), real(rnd(s, 2u)));
  precise real2 disk = random_in_unit_disk(real(rnd(s, 0u)), real(rnd(s, 1u)));
  e.disk_x = disk.x;
  e.disk_y = disk.y;
  uvec3 words =
      to_fixed(e.sample_value, float(RTVK_PROBE_SAMPLE_LIMIT), float(RTVK_PROBE_SUM_SCALE));
  e.fixed_low = words.x;
  e.fixed_high = words.y;
  e.fixed_top = words.z;
  e.overflows = sum_overflows(e.sample_value, float(RTVK_PROBE_SAMPLE_LIMIT)) ? 1u : 0u;
}

RTVK_KERNELS_END

#endif  // RTVK_KERNEL_PROBE_H
