// The body of the punctual lights' probe, in the kernels' language: punctual_probe.comp and the
// tests' float compilation (tests/gpu/kernels_f32.cpp) run it on the same entries and lights, so
// whatever they disagree on is the device's arithmetic.
#ifndef RTVK_PUNCTUAL_PROBE_H
#define RTVK_PUNCTUAL_PROBE_H
#include "kernel_lang.h"
#include "probe_types.h"
#include "punctual.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::punctual_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

inline void run_punctual_probe(PUNCTUAL_PARAM INOUT(punctual_probe_entry) e) {
  light_sample s = punctual_sample(PUNCTUALS e.light, e.p, e.u);
  e.wi = s.wi;
  e.distance = s.distance;
  e.radiance = s.radiance;
  e.pdf = s.pdf;
  e.delta = s.delta ? 1u : 0u;
  e.count = punctual_count(PUNCTUALS_ONLY);
  e.sun_radiance = sun_radiance(PUNCTUALS e.query);
  e.sun_pdf = sun_pdf(PUNCTUALS e.light, e.query);
}

RTVK_KERNELS_END

#endif  // RTVK_PUNCTUAL_PROBE_H
