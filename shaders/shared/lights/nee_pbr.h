// Next-event estimation at a PBR material (pbr.h's model): path_hit_pbr's step (pbr_shading.h)
// with a light sample beside the BSDF's, both weighed by the power heuristic (nee.h).
#ifndef RTVK_NEE_PBR_H
#define RTVK_NEE_PBR_H
#include "kernel_lang.h"
#include "nee.h"
#include "pbr_shading.h"

RTVK_KERNELS_BEGIN

// Whether world direction d leaves on the side its local z (in the shading frame) says: the
// no-leak rule against the surface's own normal (path_hit_pbr's).
inline bool pbr_side_agrees(hit_record rec, real3 d, real local_z) {
  precise real facing = dot3(d, rec.normal);
  return local_z > real(0.0) ? facing > real(0.0) : facing < real(0.0);
}

// p.r hit `rec` on a PBR material (m, n, coat_n as path_hit_pbr takes them), under next-event
// estimation: one light sample, weighted by pbr_eval over the power heuristic of its density
// against pbr_pdf's, and the BSDF's sample as the path (its density kept for the next hit's
// weight; a delta lobe's none). The model is evaluated at both directions in one loop of two
// trips, so that its code is compiled once into the render shader.
inline bool path_hit_pbr_nee(NEE_PARAM precise INOUT(path_state) p, hit_record rec, pbr_surface m,
                             real3 n, real3 coat_n, precise OUT(real3) c) {
  c = p.radiance;
  onb b = onb_from_w(n);
  precise real3 wo = to_frame(b, -unit_vector(p.r.direction));
  if (m.clearcoat > real(0.0)) m.clearcoat_normal = unit_vector(to_frame(b, coat_n));
  if (!(wo.z > real(0.0))) return true;
  pbr_lobes l = pbr_lobes_of(m, wo);
  random_stream s = at_bounce(p.s, p.depth + 1u);
  precise real3 origin = rec.p + rec.offset * rec.normal;
  precise real choice;
  light_sample ls = nee_draw_at(NEE_LIGHTS origin, rec.normal, p.r.time, s, choice);
  precise real3 u =
      real3(real(rnd(s, dim_pbr_lobe)), real(rnd(s, dim_pbr_a)), real(rnd(s, dim_pbr_b)));
  precise real3 wi;
  precise real3 weight;
  precise real delta_pdf;
  bool delta = false;
  bool drawn = pbr_draw_direction(m, l, wo, u, wi, weight, delta_pdf, delta);
  precise real3 light_wi = to_frame(b, ls.wi);
  bool lit = ls.pdf > real(0.0) && pbr_side_agrees(rec, ls.wi, light_wi.z);
  precise real3 f_light = real3(0.0);
  precise real pdf_light = real(0.0);
  precise real pdf_bsdf = real(0.0);
  for (int k = 0; k < 2; ++k) {
    if (k == 0 ? !lit : (!drawn || delta)) continue;
    precise real3 d = k == 0 ? light_wi : wi;
    precise real3 f = pbr_eval_lobes(m, l, wo, d);
    precise real pdf = pbr_pdf_lobes(m, l, wo, d);
    if (k == 0) {
      f_light = f;
      pdf_light = pdf;
    } else {
      weight = pdf > real(0.0) ? f / pdf : real3(0.0);
      pdf_bsdf = pdf;
    }
  }
  if (lit) nee_queue(p, scatter_origin(rec, ls.wi), ls, choice, f_light, pdf_light);
  precise real3 direction = onb_local(b, wi);
  precise real total = weight.x + weight.y + weight.z;
  if (!drawn || !pbr_side_agrees(rec, direction, wi.z) || !(total > real(0.0))) {
    nee_end(p);  // absorbed, a leak, or not a number
    return false;
  }
  p.mis_pdf = delta ? real(0.0) : pdf_bsdf;
  p.r = ray(scatter_origin(rec, direction), direction, p.r.time);
  p.mis_origin = p.r.origin;
  p.mis_at = origin;
  p.mis_normal = rec.normal;
  p.throughput *= weight;
  ++p.depth;
  if (!nee_roulette(p, s)) nee_end(p);
  return false;
}

RTVK_KERNELS_END

#endif  // RTVK_NEE_PBR_H
