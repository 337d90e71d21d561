// The body of the light probe, in the kernels' language: light_probe.comp and the tests' float
// compilation (tests/gpu/kernels_f32.cpp) run it on the same entries.
#ifndef RTVK_LIGHT_PROBE_H
#define RTVK_LIGHT_PROBE_H
#include "kernel_lang.h"
#include "pdf.h"
#include "probe_types.h"
#include "shared_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::light_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

inline void run_light_probe(INOUT(light_probe_entry) e) {
  light_record l;
  l.a = e.light.a;
  l.kind = e.light.kind;
  l.u = e.light.u;
  l.radius = e.light.radius;
  l.v = e.light.v;
  l.area = e.light.area;
  l.normal = e.light.normal;
  e.sampled = light_random(l, e.origin, e.time, e.r1, e.r2);
  e.pdf = light_pdf(l, e.origin, e.direction, e.time);
  e.sampled_pdf = light_pdf(l, e.origin, e.sampled, e.time);
  e.cosine_sampled = cosine_random(e.normal, e.r1, e.r2);
  e.cosine = cosine_pdf(e.normal, e.direction);
}

RTVK_KERNELS_END

#endif  // RTVK_LIGHT_PROBE_H
