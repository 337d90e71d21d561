// The body of the PBR probe, in the kernels' language: pbr_probe.comp and the tests' float
// compilation (tests/gpu/kernels_f32.cpp) run it on the same entries, so whatever they disagree on
// is the device's arithmetic.
#ifndef RTVK_PBR_PROBE_H
#define RTVK_PBR_PROBE_H
#include "kernel_lang.h"
#include "pbr.h"
#include "probe_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
using ::rtvk::gpu::pbr_probe_entry;  // the struct that crosses; GLSL sees it unqualified
#endif

// The entry's material as pbr.h takes it.
inline pbr_surface pbr_probe_surface(pbr_probe_entry e) {
  pbr_surface m = pbr_surface_of(e.base_color, e.metallic, e.roughness);
  m.eta = e.eta;
  m.specular = e.specular;
  m.specular_color = e.specular_color;
  m.transmission = e.transmission;
  m.thin = e.thin != 0u;
  m.clearcoat = e.clearcoat;
  m.clearcoat_roughness = e.clearcoat_roughness;
  m.clearcoat_normal = e.clearcoat_normal;
  m.sheen_color = e.sheen_color;
  m.sheen_roughness = e.sheen_roughness;
  return m;
}

inline void run_pbr_probe(INOUT(pbr_probe_entry) e) {
  pbr_surface m = pbr_probe_surface(e);
  precise real3 wi;
  precise real3 weight;
  precise real pdf;
  bool delta;
  e.sampled = pbr_sample(m, e.wo, e.u, wi, weight, pdf, delta) ? 1u : 0u;
  e.wi = wi;
  e.weight = weight;
  e.pdf = pdf;
  e.delta = delta ? 1u : 0u;
  e.eval_sampled = pbr_eval(m, e.wo, wi);
  e.pdf_sampled = pbr_pdf(m, e.wo, wi);
  e.eval_query = pbr_eval(m, e.wo, e.wi_query);
  e.pdf_query = pbr_pdf(m, e.wo, e.wi_query);
}

RTVK_KERNELS_END

#endif  // RTVK_PBR_PROBE_H
