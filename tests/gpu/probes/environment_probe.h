// The body of the environment probe, in the kernels' language: environment_probe.comp and the
// tests' float compilation (tests/gpu/kernels_f32.cpp) run it on the same entries and map, so
// whatever they disagree on is the device's arithmetic.
#ifndef RTVK_ENVIRONMENT_PROBE_H
#define RTVK_ENVIRONMENT_PROBE_H
#include "environment.h"
#include "kernel_lang.h"
#include "probe_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::environment_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

inline void run_environment_probe(ENV_PARAM INOUT(environment_probe_entry) e) {
  e.radiance_query = environment_radiance(ENV e.query);
  e.pdf_query = environment_pdf(ENV e.query);
  light_sample ls = environment_sample(ENV real2(e.ux, e.uy));
  e.wi = ls.wi;
  e.pdf = ls.pdf;
  e.radiance = ls.radiance;
  e.pdf_sampled = environment_pdf(ENV ls.wi);
  e.trips = environment_sample_trips(ENV_ALONE);
  e.visible = environment_visible(ENV_ALONE) ? 1u : 0u;
}

RTVK_KERNELS_END

#endif  // RTVK_ENVIRONMENT_PROBE_H
