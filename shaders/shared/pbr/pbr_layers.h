// What pbr.h computes once per outgoing direction: the lobes' parameters and colors, the albedos
// its energy compensation and layering need (bilinear reads of bsdf_tables.h), and the lobe
// choice probabilities of pbr_sample. docs/materials.md's model section gives the formulas.
#ifndef RTVK_PBR_LAYERS_H
#define RTVK_PBR_LAYERS_H
#include "bsdf_tables.h"
#include "kernel_lang.h"
#include "microfacet.h"
#include "pbr_surface.h"

RTVK_KERNELS_BEGIN

// |eta - 1| below this refracts nothing: a refracting wall of (nearly) equal indices passes the
// light straight through however rough it is (Walter's half vector o + eta i vanishes there), so
// its transmission is a delta lobe along -wo.
const real pbr_eta_one = real(1e-3);

// The sheen distribution's smallest alpha (bsdf_tables.h is integrated with the same bound).
const real sheen_alpha_min = real(1e-2);

// A bilinear read position in the tables: the lower-left entry and the weights.
struct table_pos {
  int at;   // row * size + column of the lower-left entry
  real fx;  // weight of the next column (cosine)
  real fy;  // weight of the next row (roughness)
  int row;  // the lower row, for the 1-D tables
};

inline precise table_pos table_pos_of(real mu, real roughness) {
  precise real n1 = real(bsdf_table_size - 1);
  precise real x = sqrt(min(max(mu, real(0.0)), real(1.0))) * n1;  // columns at (i / 31)^2
  precise real y = min(max(roughness, real(0.0)), real(1.0)) * n1;
  int ix = min(int(x), bsdf_table_size - 2);
  int iy = min(int(y), bsdf_table_size - 2);
  table_pos p;
  p.at = iy * bsdf_table_size + ix;
  p.fx = x - real(ix);
  p.fy = y - real(iy);
  p.row = iy;
  return p;
}

// One bilinear read per table, the table at offset `t` of bsdf_tables.h's one array.
#define RTVK_TABLE_READ(fn, t)                                                                     \
  inline precise real fn(table_pos p) {                                                            \
    int i = t + p.at;                                                                              \
    precise real a = real(BSDF_TABLE(i)) + (real(BSDF_TABLE(i + 1)) - real(BSDF_TABLE(i))) * p.fx; \
    int j = i + bsdf_table_size;                                                                   \
    precise real b = real(BSDF_TABLE(j)) + (real(BSDF_TABLE(j + 1)) - real(BSDF_TABLE(j))) * p.fx; \
    return a + (b - a) * p.fy;                                                                     \
  }
#define RTVK_ROW_READ(fn, t)                                                             \
  inline precise real fn(table_pos p) {                                                  \
    int i = t + p.row;                                                                   \
    return real(BSDF_TABLE(i)) + (real(BSDF_TABLE(i + 1)) - real(BSDF_TABLE(i))) * p.fy; \
  }
RTVK_TABLE_READ(read_ggx_e, bsdf_ggx_e)
RTVK_TABLE_READ(read_ggx_es, bsdf_ggx_es)
RTVK_TABLE_READ(read_sheen_e, bsdf_sheen_e)
RTVK_ROW_READ(read_ggx_e_avg, bsdf_ggx_e_avg)
RTVK_ROW_READ(read_ggx_es_avg, bsdf_ggx_es_avg)
RTVK_ROW_READ(read_sheen_norm, bsdf_sheen_norm)

inline precise real max3(real3 v) {
  return max(v.x, max(v.y, v.z));
}

// Kulla and Conty's Fresnel of the multiply scattered energy: F_avg^2 E_avg / (1 - F_avg (1 -
// E_avg)), F_avg = F0 + (1 - F0) / 21 (Schlick's cosine-weighted average).
inline precise real3 ms_fresnel(real3 f0, real3 f90, real e_avg) {
  precise real3 f_avg = f0 + (f90 - f0) * real(1.0 / 21.0);
  return f_avg * f_avg * e_avg / (real3(1.0) - f_avg * (real(1.0) - e_avg));
}

// A GGX reflection lobe's albedo toward w, with Fresnel f0 + (f90 - f0) (1 - w.h)^5 and its
// multiple scattering: f0 (E - Es) + f90 Es + F_ms (1 - E).
inline precise real ggx_albedo(real e, real es, real e_avg, real f0, real f90) {
  precise real f_avg = f0 + (f90 - f0) * real(1.0 / 21.0);
  precise real fms = f_avg * f_avg * e_avg / (real(1.0) - f_avg * (real(1.0) - e_avg));
  return f0 * (e - es) + f90 * es + fms * (real(1.0) - e);
}

// The lobes of one pbr_surface seen from one wo.
struct pbr_lobes {
  real alpha;         // the base's GGX alpha
  bool base_smooth;   // alpha < ggx_alpha_delta: the reflection and transmission are deltas
  bool trans_delta;   // the transmission is a delta: smooth, or refracting at eta ~ 1
  real3 spec_f0;      // the reflection lobe's Fresnel at normal incidence: the metal's and the
  real3 spec_f90;     //   dielectric's mixed by metallic (Schlick is linear in F0 and F90)
  real3 spec_ms;      // the reflection's multiple-scattering lobe's color (Kulla-Conty)
  real e_o;           // E(wo.z, roughness), the single-scattering albedo with Fresnel 1
  real e_avg;         // E_avg(roughness)
  real ms_norm;       // 1 / (pi (1 - E_avg)), 0 where E_avg is 1
  real s_f0;          // the dielectric reflection's largest F0 (before specular's weight)
  real s_weight;      // specular: the dielectric reflection's weight
  real s_o;           // the dielectric reflection's albedo toward wo (largest channel)
  real diffuse_norm;  // 1 / (pi (1 - S_avg)): the diffuse lobe's (1 - S(wo)) (1 - S(wi)) factor
  real3 diffuse;      // (1 - metallic) (1 - transmission) base_color
  real3 trans;        // (1 - metallic) transmission base_color
  real sheen_max;     // max(sheen_color)
  real sheen_alpha;   // the Charlie distribution's alpha
  real sheen_norm;    // 1 / max(1, the sheen lobe's largest albedo) (bsdf_tables.h)
  real sheen_e_o;     // the sheen lobe's albedo toward wo, sheen color 1
  real coat_alpha;    // the coat's GGX alpha
  bool coat_smooth;   // the coat is a delta mirror
  real3 coat_n;       // clearcoat_normal normalized again (a float normal is unit only to 1e-7,
                      // and its frame's directions must agree with each other to 1e-9 and better)
  real3 coat_wo;      // wo in the coat's frame (z = coat_n)
  real coat_e_o;      // clearcoat times the coat's albedo toward wo (|wo.nc|: what the layers
                      // below lose to it, even where wo is below the coat and sees none of it)
  bool coat_on;       // clearcoat > 0 and wo above the coat: its lobe reflects
  real p_coat;        // pbr_sample's lobe choice: coat, reflection, transmission, and the
  real p_spec;        //   cosine lobe that carries the diffuse, sheen and multiple-scattering
  real p_trans;       //   lobes; they sum to 1 (or all 0: the surface is black)
  real p_cos;         //
};

// The dielectric reflection's albedo (its largest channel, times specular) toward a cosine c,
// from the tables' E, Es and E_avg there; a smooth reflection's is Schlick's Fresnel itself.
inline precise real dielectric_albedo(pbr_lobes l, real e, real es, real e_avg, real c) {
  precise real f = l.s_f0 + (real(1.0) - l.s_f0) * schlick_weight(c);
  return l.s_weight * (l.base_smooth ? f : ggx_albedo(e, es, e_avg, l.s_f0, real(1.0)));
}

// The coat's albedo (times clearcoat) toward a cosine against the coat's normal: F0 0.04.
inline precise real coat_albedo(pbr_surface m, real cos_c) {
  table_pos p = table_pos_of(abs(cos_c), m.clearcoat_roughness);
  precise real e = read_ggx_e(p);
  precise real es = read_ggx_es(p);
  return m.clearcoat * (real(0.04) * (e - es) + es);
}

inline precise real sheen_albedo(pbr_lobes l, pbr_surface m, real cos_w) {
  return l.sheen_max * read_sheen_e(table_pos_of(abs(cos_w), m.sheen_roughness));
}

// pbr_sample's lobe choice, each lobe in proportion to its estimated albedo toward wo (a floor
// keeps a lobe that is on but estimated at 0 reachable); e and es: the tables at wo.
inline precise pbr_lobes pbr_choose_lobes(pbr_surface m, pbr_lobes l, real3 wo, real e, real es) {
  precise real under_coat = real(1.0) - l.coat_e_o;
  precise real sheen_w = l.sheen_max * max(l.sheen_e_o, real(0.01));
  precise real under_sheen = under_coat * (real(1.0) - l.sheen_max * l.sheen_e_o);
  precise real spec_w = max3(l.spec_f0 * (l.e_o - es) + l.spec_f90 * es);
  precise real base_w = real(1.0) - l.s_o;
  precise real ms_w = l.base_smooth ? real(0.0) : max3(l.spec_ms) * (real(1.0) - e);
  l.p_coat = l.coat_on ? max(l.coat_e_o, real(0.01) * m.clearcoat) : real(0.0);
  l.p_spec =
      under_sheen *
      (l.base_smooth ? max3(l.spec_f0 + (l.spec_f90 - l.spec_f0) * schlick_weight(wo.z)) : spec_w);
  l.p_trans = under_sheen * max3(l.trans) * base_w;
  l.p_cos = under_coat * sheen_w + under_sheen * (max3(l.diffuse) * base_w + ms_w);
  precise real total = l.p_coat + l.p_spec + l.p_trans + l.p_cos;
  // Divided, not multiplied by 1 / total: a single lobe's probability is then exactly 1.
  precise real d = total > real(0.0) ? total : real(1.0);
  l.p_coat = l.p_coat / d;
  l.p_spec = l.p_spec / d;
  l.p_trans = l.p_trans / d;
  l.p_cos = l.p_cos / d;
  return l;
}

// The lobes of m seen from wo (wo.z > 0).
inline precise pbr_lobes pbr_lobes_of(pbr_surface m, real3 wo) {
  pbr_lobes l;
  l.alpha = m.roughness * m.roughness;
  l.base_smooth = l.alpha < ggx_alpha_delta;
  l.trans_delta = l.base_smooth || (!m.thin && abs(m.eta - real(1.0)) < pbr_eta_one);
  // The dielectric's F0 from its ior and KHR_materials_specular; the metal's is its base color.
  precise real r0 = (m.eta - real(1.0)) / (m.eta + real(1.0));
  precise real3 d_f0 = min(r0 * r0 * m.specular_color, real3(1.0));  // before specular's weight
  precise real dm = real(1.0) - m.metallic;
  l.spec_f0 = dm * m.specular * d_f0 + m.metallic * m.base_color;
  l.spec_f90 = real3(dm * m.specular + m.metallic);
  table_pos po = table_pos_of(wo.z, m.roughness);
  precise real e = read_ggx_e(po);
  precise real es = read_ggx_es(po);
  precise real e_avg = read_ggx_e_avg(po);
  precise real es_avg = read_ggx_es_avg(po);
  l.e_o = l.base_smooth ? real(1.0) : e;
  l.e_avg = e_avg;
  l.ms_norm =
      l.base_smooth || e_avg >= real(1.0) ? real(0.0) : real(1.0) / (pi * (real(1.0) - e_avg));
  l.spec_ms = dm * m.specular * ms_fresnel(d_f0, real3(1.0), e_avg) +
              m.metallic * ms_fresnel(m.base_color, real3(1.0), e_avg);
  // The dielectric reflection's albedo from its largest channel: what its base layer loses.
  l.s_f0 = max3(d_f0);
  l.s_weight = m.specular;
  l.s_o = dielectric_albedo(l, e, es, e_avg, wo.z);
  // The average: a smooth reflection's is Schlick's, F0 + (1 - F0) / 21.
  precise real s_avg = l.base_smooth
                           ? m.specular * (l.s_f0 + (real(1.0) - l.s_f0) * real(1.0 / 21.0))
                           : dielectric_albedo(l, e_avg, es_avg, e_avg, real(1.0));
  l.diffuse_norm = s_avg >= real(1.0) ? real(0.0) : real(1.0) / (pi * (real(1.0) - s_avg));
  l.diffuse = dm * (real(1.0) - m.transmission) * m.base_color;
  l.trans = dm * m.transmission * m.base_color;
  // Sheen.
  l.sheen_max = max3(m.sheen_color);
  l.sheen_alpha = max(m.sheen_roughness * m.sheen_roughness, sheen_alpha_min);
  table_pos ps = table_pos_of(wo.z, m.sheen_roughness);
  l.sheen_norm = read_sheen_norm(ps);
  l.sheen_e_o = read_sheen_e(ps);
  // Clearcoat, in its own frame.
  l.coat_alpha = m.clearcoat_roughness * m.clearcoat_roughness;
  l.coat_smooth = l.coat_alpha < ggx_alpha_delta;
  l.coat_n = unit_vector(m.clearcoat_normal);
  l.coat_wo = onb_to_inner(l.coat_n, wo);
  l.coat_on = m.clearcoat > real(0.0) && l.coat_wo.z > real(0.0);
  l.coat_e_o = coat_albedo(m, l.coat_wo.z);
  return pbr_choose_lobes(m, l, wo, e, es);
}

RTVK_KERNELS_END

#endif  // RTVK_PBR_LAYERS_H
