// The glTF 2.0 metallic-roughness BSDF (the specification's appendix B) and its KHR_materials_*
// layers, one source for both backends: evaluate, sample and density, in the shading frame.
// docs/materials.md's model section gives the formulas and the references.
//
// The frame: z is the shading normal at the hit, facing the side the ray came from, so the
// outgoing direction wo (toward where the ray came from) has wo.z > 0; wi with wi.z > 0 is
// reflection, wi.z < 0 transmission. Both are unit vectors. The caller builds the frame (onb) and
// turns directions in and out of it.
//
// The lobes, top to bottom: the clearcoat's GGX reflection; the sheen (Charlie); the base, which
// is metallic's mix of the metal (GGX reflection, Schlick F0 = base color) and the dielectric
// (GGX reflection, F0 from ior and KHR_materials_specular, over a Lambertian diffuse or, as
// transmission says, a GGX transmission), each GGX reflection with Kulla and Conty's multiple
// scattering. Each layer takes from those below it the energy it reflects (albedo scaling).
#ifndef RTVK_PBR_H
#define RTVK_PBR_H
#include "kernel_lang.h"
#include "microfacet.h"
#include "pbr_layers.h"
#include "pbr_surface.h"
#include "random.h"

RTVK_KERNELS_BEGIN

// What the coat and the sheen leave to the layers under them between wo and wi: the smaller of
// the two directions' (1 - albedo), as KHR_materials_sheen writes it; reciprocal, and never more
// than wo's, so that no layer adds energy.
inline precise real pbr_under_coat(pbr_surface m, pbr_lobes l, real3 wi) {
  precise real c_i = coat_albedo(m, dot3(wi, l.coat_n));
  return real(1.0) - max(l.coat_e_o, c_i);
}
inline precise real pbr_under_sheen(pbr_surface m, pbr_lobes l, real3 wi) {
  return real(1.0) -
         l.sheen_max * max(l.sheen_e_o, read_sheen_e(table_pos_of(abs(wi.z), m.sheen_roughness)));
}

// The rough transmission's half vector, facing +z: thin walls mirror wi back above (their light
// does not bend); else the generalized half vector of refraction, wo + eta wi.
inline precise real3 pbr_trans_half(pbr_surface m, real3 wo, real3 wi) {
  precise real3 h = m.thin ? wo + real3(wi.x, wi.y, -wi.z) : wo + m.eta * wi;
  h = unit_vector(h);
  return h.z < real(0.0) ? -h : h;
}

// Whether a microfacet with cosine c to wo reflects all the refraction would take: the exact
// Fresnel's total internal reflection (not Schlick's), for a ray leaving a denser medium.
inline bool pbr_total_reflection(pbr_surface m, pbr_lobes l, real c) {
  precise real sin2 = real(1.0) - c * c;
  precise real eta2 = m.eta * m.eta;
  return !l.trans_delta && !m.thin && sin2 >= eta2;
}

// The base's reflection (single and multiple scattering, and the refraction's total internal
// reflection) and diffuse, wi.z > 0.
inline precise real3 pbr_eval_base_reflection(pbr_surface m, pbr_lobes l, real3 wo, real3 wi) {
  table_pos pi_ = table_pos_of(wi.z, m.roughness);
  precise real e_i = read_ggx_e(pi_);
  precise real es_i = read_ggx_es(pi_);
  precise real s_i = dielectric_albedo(l, e_i, es_i, l.e_avg, wi.z);
  precise real3 f = l.diffuse * ((real(1.0) - l.s_o) * (real(1.0) - s_i) * l.diffuse_norm * wi.z);
  if (!l.base_smooth) {
    precise real3 h = unit_vector(wo + wi);
    precise real3 fr = fresnel_schlick(l.spec_f0, l.spec_f90, dot3(wo, h));
    f += fr * (ggx_d(h, l.alpha) * ggx_g2(wo, wi, l.alpha) / (real(4.0) * wo.z));
    f += l.spec_ms * ((real(1.0) - l.e_o) * (real(1.0) - e_i) * l.ms_norm * wi.z);
    // What the refraction's microfacets reflect totally (leaving a denser medium).
    precise real tir = pbr_total_reflection(m, l, dot3(wo, h)) ? real(1.0) : real(0.0);
    f += l.trans * (min(real(1.0) - l.s_o, real(1.0) - s_i) * tir * ggx_d(h, l.alpha) *
                    ggx_g2(wo, wi, l.alpha) / (real(4.0) * wo.z));
  }
  return f;
}

// The base's rough transmission, wi.z < 0: Walter et al. 2007 (without the 1 / eta^2 of
// radiance, as the book's dielectric), or for thin walls the reflection lobe mirrored below.
inline precise real3 pbr_eval_base_transmission(pbr_surface m, pbr_lobes l, real3 wo, real3 wi) {
  if (l.trans_delta) return real3(0.0);
  precise real3 h = pbr_trans_half(m, wo, wi);
  precise real oh = dot3(wo, h);
  precise real ih = dot3(wi, h);
  // What the reflection leaves, the smaller of the two directions' share: reciprocal (S is the
  // same at eta and 1 / eta), and never more than wo's.
  table_pos pi_ = table_pos_of(-wi.z, m.roughness);
  precise real s_i = dielectric_albedo(l, read_ggx_e(pi_), read_ggx_es(pi_), l.e_avg, -wi.z);
  precise real3 t = l.trans * min(real(1.0) - l.s_o, real(1.0) - s_i);
  if (m.thin) {
    precise real3 wr = real3(wi.x, wi.y, -wi.z);
    return t * (ggx_d(h, l.alpha) * ggx_g2(wo, wr, l.alpha) / (real(4.0) * wo.z));
  }
  if (oh <= real(0.0) || ih >= real(0.0)) return real3(0.0);
  precise real den = oh + m.eta * ih;
  return t * (ggx_d(h, l.alpha) * ggx_g2(wo, wi, l.alpha) * oh * -ih * m.eta * m.eta /
              (den * den * wo.z));
}

// The coat's rough reflection, F D G2 |wi.z| / (4 max(wo.nc wi.z, wi.nc wo.z)): with the coat's
// normal nc the base's, the microfacet BRDF; tilted, symmetric in wo and wi (reciprocal) and never
// more than F D G2 / (4 wo.nc), whose integral is the coat's albedo (so it adds no energy).
inline precise real pbr_eval_coat(pbr_surface m, pbr_lobes l, real3 wo, real3 wi) {
  precise real3 ic = onb_to_inner(l.coat_n, wi);
  if (!l.coat_on || l.coat_smooth || ic.z <= real(0.0) || wi.z <= real(0.0)) return real(0.0);
  precise real3 h = unit_vector(l.coat_wo + ic);
  precise real f = real(0.04) + real(0.96) * schlick_weight(dot3(l.coat_wo, h));
  precise real cosines = max(l.coat_wo.z * wi.z, ic.z * wo.z);
  return m.clearcoat * f * ggx_d(h, l.coat_alpha) * ggx_g2(l.coat_wo, ic, l.coat_alpha) * wi.z /
         (real(4.0) * cosines);
}

inline precise real3 pbr_eval_lobes(pbr_surface m, pbr_lobes l, real3 wo, real3 wi) {
  if (wo.z <= real(0.0) || wi.z == real(0.0)) return real3(0.0);
  precise real3 f = real3(0.0);
  if (wi.z > real(0.0)) {
    precise real3 h = unit_vector(wo + wi);
    f = m.sheen_color *
        (charlie_d(h, l.sheen_alpha) * sheen_visibility(wo.z, wi.z) * wi.z * l.sheen_norm);
    f += pbr_under_sheen(m, l, wi) * pbr_eval_base_reflection(m, l, wo, wi);
  } else {
    f = pbr_under_sheen(m, l, wi) * pbr_eval_base_transmission(m, l, wo, wi);
  }
  return pbr_under_coat(m, l, wi) * f + real3(pbr_eval_coat(m, l, wo, wi));
}

inline precise real pbr_pdf_lobes(pbr_surface m, pbr_lobes l, real3 wo, real3 wi) {
  if (wo.z <= real(0.0) || wi.z == real(0.0)) return real(0.0);
  precise real p = real(0.0);
  precise real3 ic = onb_to_inner(l.coat_n, wi);
  if (l.p_coat > real(0.0) && !l.coat_smooth && ic.z > real(0.0) && wi.z > real(0.0)) {
    precise real3 h = unit_vector(l.coat_wo + ic);
    p += l.p_coat * ggx_pdf_vndf(l.coat_wo, h, l.coat_alpha) / (real(4.0) * dot3(l.coat_wo, h));
  }
  if (wi.z > real(0.0)) {
    p += l.p_cos * wi.z / pi;
    if (!l.base_smooth) {
      precise real3 h = unit_vector(wo + wi);
      precise real tir = pbr_total_reflection(m, l, dot3(wo, h)) ? l.p_trans : real(0.0);
      p += (l.p_spec + tir) * ggx_pdf_vndf(wo, h, l.alpha) / (real(4.0) * dot3(wo, h));
    }
  } else if (!l.trans_delta && l.p_trans > real(0.0)) {
    precise real3 h = pbr_trans_half(m, wo, wi);
    precise real oh = dot3(wo, h);
    precise real ih = dot3(wi, h);
    precise real den = oh + m.eta * ih;
    precise real jac = m.thin ? real(1.0) / (real(4.0) * oh) : m.eta * m.eta * -ih / (den * den);
    bool ok = m.thin || (oh > real(0.0) && ih < real(0.0));
    p += ok ? l.p_trans * ggx_pdf_vndf(wo, h, l.alpha) * jac : real(0.0);
  }
  return p;
}

// f(wo, wi) |wi.z|: the BSDF times the cosine at wi, per steradian. Delta lobes (a smooth
// surface's mirror or refraction) are not in it: only pbr_sample finds those.
inline precise real3 pbr_eval(pbr_surface m, real3 wo, real3 wi) {
  if (wo.z <= real(0.0)) return real3(0.0);
  return pbr_eval_lobes(m, pbr_lobes_of(m, wo), wo, wi);
}

// The density per steradian with which pbr_sample draws wi given wo (its non-delta lobes).
inline precise real pbr_pdf(pbr_surface m, real3 wo, real3 wi) {
  if (wo.z <= real(0.0)) return real(0.0);
  return pbr_pdf_lobes(m, pbr_lobes_of(m, wo), wo, wi);
}

// The smooth lobes' directions and values (delta: per unit of their choice probability).
inline precise real3 pbr_delta_value(pbr_surface m, pbr_lobes l, real3 wo, real3 wi, int lobe) {
  precise real3 base =
      lobe == 1 ? fresnel_schlick(l.spec_f0, l.spec_f90, wo.z) : l.trans * (real(1.0) - l.s_o);
  precise real3 under = pbr_under_coat(m, l, wi) * pbr_under_sheen(m, l, wi) * base;
  precise real coat = m.clearcoat * (real(0.04) + real(0.96) * schlick_weight(l.coat_wo.z));
  return lobe == 0 ? real3(coat) : under;
}

// A direction from one lobe (0 coat, 1 reflection, 2 transmission, 3 cosine) with u.y and u.z.
// False where it has none (below the surface, or a thin wall's reflection below it).
inline bool pbr_draw(pbr_surface m, pbr_lobes l, real3 wo, int lobe, real3 u,
                     precise OUT(real3) wi) {
  real2 v = real2(u.y, u.z);
  wi = real3(0.0, 0.0, 1.0);
  if (lobe == 0) {
    precise real3 ic = l.coat_smooth
                           ? real3(-l.coat_wo.x, -l.coat_wo.y, l.coat_wo.z)
                           : reflect_about(l.coat_wo, ggx_sample_vndf(l.coat_wo, l.coat_alpha, v));
    wi = onb_to_outer(l.coat_n, ic);
    if (ic.z <= real(0.0)) return false;
  } else if (lobe == 1) {
    wi = l.base_smooth ? real3(-wo.x, -wo.y, wo.z)
                       : reflect_about(wo, ggx_sample_vndf(wo, l.alpha, v));
  } else if (lobe == 2) {
    precise real3 h = l.trans_delta ? real3(0.0, 0.0, 1.0) : ggx_sample_vndf(wo, l.alpha, v);
    precise real eta_off = m.eta - real(1.0);
    if (m.thin || (l.trans_delta && abs(eta_off) < pbr_eta_one)) {
      precise real3 r = reflect_about(wo, h);
      wi = real3(r.x, r.y, -r.z);   // thin: the light goes through without bending
      if (l.trans_delta) wi = -wo;  // exactly
      if (r.z <= real(0.0)) return false;
    } else if (refract_through(wo, h, m.eta, wi)) {
      if (wi.z >= real(0.0)) return false;
    } else {
      wi = reflect_about(wo, h);  // total internal reflection: the light stays inside
      if (wi.z <= real(0.0)) return false;
    }
  } else {
    precise real r = sqrt(u.y);
    precise real phi = real(2.0) * pi * u.z;
    wi = real3(r * cos(phi), r * sin(phi), sqrt(max(real(0.0), real(1.0) - u.y)));
  }
  return true;
}

// pbr_sample's draw with the lobes of wo given (pbr_lobes_of), without the weight of a non-delta
// direction: the caller evaluates it, as the path step does, which mixes the lights' density in.
// Each of the model's parts is then compiled once into the render shader (sampling, evaluating
// and the density each inlined twice made lavapipe compile it for minutes). wi: the direction;
// delta: it came from a delta lobe, whose weight (its value over its choice probability) and
// choice probability are set; else they are 0. False: no direction (absorbed).
inline bool pbr_draw_direction(pbr_surface m, pbr_lobes l, real3 wo, real3 u, precise OUT(real3) wi,
                               precise OUT(real3) weight, precise OUT(real) pdf, OUT(bool) delta) {
  wi = real3(0.0, 0.0, 1.0);
  weight = real3(0.0);
  pdf = real(0.0);
  delta = false;
  if (wo.z <= real(0.0)) return false;
  int lobe = u.x < l.p_coat                          ? 0
             : u.x < l.p_coat + l.p_spec             ? 1
             : u.x < l.p_coat + l.p_spec + l.p_trans ? 2
             : l.p_cos > real(0.0)                   ? 3
             : l.p_trans > real(0.0)                 ? 2
             : l.p_spec > real(0.0)                  ? 1
                                                     : 0;
  precise real p_lobe = lobe == 0   ? l.p_coat
                        : lobe == 1 ? l.p_spec
                        : lobe == 2 ? l.p_trans
                                    : l.p_cos;
  if (p_lobe <= real(0.0)) return false;
  delta =
      (lobe == 0 && l.coat_smooth) || (lobe == 1 && l.base_smooth) || (lobe == 2 && l.trans_delta);
  if (!pbr_draw(m, l, wo, lobe, u, wi)) return false;
  if (delta) {
    if (wi.z == real(0.0) || (lobe == 0 && wi.z < real(0.0))) return false;
    pdf = p_lobe;
    weight = pbr_delta_value(m, l, wo, wi, lobe) / p_lobe;
    return true;
  }
  // The transmission's lobe reflects where its microfacets reflect totally.
  return lobe == 2 ? wi.z != real(0.0) : wi.z > real(0.0);
}

// Draws wi given wo from three uniform numbers u in [0, 1): weight is f |wi.z| / pdf, the factor
// a path's throughput takes. delta: wi came from a delta lobe (pdf is then that lobe's choice
// probability, and no other density may be mixed with it). False: no direction (absorbed).
// u.x chooses the lobe (coat, reflection, transmission, cosine) in proportion to their albedo
// estimates; u.y and u.z draw the direction within it.
inline bool pbr_sample(pbr_surface m, real3 wo, real3 u, precise OUT(real3) wi,
                       precise OUT(real3) weight, precise OUT(real) pdf, OUT(bool) delta) {
  pbr_lobes l = pbr_lobes_of(m, wo);
  if (!pbr_draw_direction(m, l, wo, u, wi, weight, pdf, delta)) return false;
  if (delta) return true;
  pdf = pbr_pdf_lobes(m, l, wo, wi);
  if (!(pdf > real(0.0))) return false;
  weight = pbr_eval_lobes(m, l, wo, wi) / pdf;
  return true;
}

RTVK_KERNELS_END

#endif  // RTVK_PBR_H
