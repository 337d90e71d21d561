// Microfacet pieces of pbr.h, one source for both backends: the GGX (Trowbridge-Reitz)
// distribution, its height-correlated Smith shadowing-masking, the sampling of its visible
// normals (Heitz 2018, by Dupuy and Benyoub's spherical caps) and their density, Schlick's and the
// exact dielectric Fresnel, and the Charlie sheen distribution (Estevez and Kulla 2017). All in a
// frame whose z is the distribution's mean normal.
#ifndef RTVK_MICROFACET_H
#define RTVK_MICROFACET_H
#include "kernel_lang.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

// GGX alpha below this is a delta lobe (a smooth surface): pbr_sample returns delta = true and
// pbr_eval and pbr_pdf leave it out. pbrt-v4 uses the same bound; 1e-3 is roughness 0.0316.
const real ggx_alpha_delta = real(1e-3);

// D(h) = alpha^2 / (pi ((h.z^2 (alpha^2 - 1) + 1)^2)), normalized: the integral of D(h) h.z is 1.
inline precise real ggx_d(real3 h, real alpha) {
  precise real a2 = alpha * alpha;
  precise real t = h.z * h.z * (a2 - real(1.0)) + real(1.0);
  return a2 / (pi * t * t);
}

// Smith's Lambda(w) = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2.
inline precise real ggx_lambda(real3 w, real alpha) {
  precise real z2 = max(w.z * w.z, real(1e-20));
  precise real t2 = (w.x * w.x + w.y * w.y) / z2;
  return real(0.5) * (sqrt(real(1.0) + alpha * alpha * t2) - real(1.0));
}

// The masking of one direction, G1 = 1 / (1 + Lambda).
inline precise real ggx_g1(real3 w, real alpha) {
  return real(1.0) / (real(1.0) + ggx_lambda(w, alpha));
}

// Height-correlated masking-shadowing, G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (Heitz 2014).
inline precise real ggx_g2(real3 wo, real3 wi, real alpha) {
  return real(1.0) / (real(1.0) + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// A visible normal of GGX seen from w (w.z > 0), from two uniform numbers: Heitz 2018's
// stretch-sample-unstretch, the hemisphere of visible normals sampled as a spherical cap (Dupuy
// and Benyoub 2023), which has no branch.
inline precise real3 ggx_sample_vndf(real3 w, real alpha, real2 u) {
  precise real3 s = unit_vector(real3(w.x * alpha, w.y * alpha, w.z));
  precise real phi = real(2.0) * pi * u.x;
  precise real z = (real(1.0) - u.y) * (real(1.0) + s.z) - s.z;
  precise real r = sqrt(max(real(1.0) - z * z, real(0.0)));
  precise real3 h = real3(r * cos(phi), r * sin(phi), z) + s;
  return unit_vector(real3(h.x * alpha, h.y * alpha, max(h.z, real(0.0))));
}

// The density of ggx_sample_vndf per steradian of h: D_w(h) = G1(w) max(0, w.h) D(h) / w.z.
inline precise real ggx_pdf_vndf(real3 w, real3 h, real alpha) {
  return ggx_g1(w, alpha) * max(dot3(w, h), real(0.0)) * ggx_d(h, alpha) / w.z;
}

// Schlick's weight (1 - c)^5: F = F0 + (F90 - F0) schlick_weight(c).
inline precise real schlick_weight(real c) {
  precise real m = min(max(real(1.0) - c, real(0.0)), real(1.0));
  precise real m2 = m * m;
  return m2 * m2 * m;
}

inline precise real3 fresnel_schlick(real3 f0, real3 f90, real c) {
  return f0 + (f90 - f0) * schlick_weight(c);
}

// The exact Fresnel reflectance of a dielectric interface for unpolarized light: c the cosine
// on the incident side, eta the index beyond the interface over the index before it. 1 under
// total internal reflection.
inline precise real fresnel_dielectric(real c, real eta) {
  precise real s2 = (real(1.0) - c * c) / (eta * eta);  // sin^2 of the transmitted angle
  if (s2 >= real(1.0)) return real(1.0);
  precise real ct = sqrt(real(1.0) - s2);
  precise real rs = (c - eta * ct) / (c + eta * ct);
  precise real rp = (eta * c - ct) / (eta * c + ct);
  return real(0.5) * (rs * rs + rp * rp);
}

// The mirror of w about the unit normal n.
inline precise real3 reflect_about(real3 w, real3 n) {
  return real(2.0) * dot3(w, n) * n - w;
}

// The refraction of w (pointing away from the surface, on n's side) through the interface whose
// normal is n, eta = index beyond over index before. False under total internal reflection.
inline bool refract_through(real3 w, real3 n, real eta, precise OUT(real3) t) {
  precise real c = dot3(w, n);
  precise real s2 = (real(1.0) - c * c) / (eta * eta);
  t = real3(0.0);
  if (s2 >= real(1.0)) return false;
  precise real ct = sqrt(real(1.0) - s2);
  t = -w / eta + (c / eta - ct) * n;
  return true;
}

// The Charlie sheen distribution (Estevez and Kulla 2017): (2 + 1/alpha) sin^(1/alpha)(theta_h)
// / (2 pi), normalized like D (the integral of D(h) h.z is 1).
inline precise real charlie_d(real3 h, real alpha) {
  precise real s2 = max(real(1.0) - h.z * h.z, real(0.0));
  return (real(2.0) + real(1.0) / alpha) * pow(s2, real(0.5) / alpha) / (real(2.0) * pi);
}

// Neubelt and Pettineo's visibility for sheen (the one KHR_materials_sheen offers as the cheap
// alternative to Estevez and Kulla's fitted one): V = 1 / (4 (l + v - l v)); f = D V.
inline precise real sheen_visibility(real cos_o, real cos_i) {
  return real(1.0) / (real(4.0) * (cos_i + cos_o - cos_i * cos_o));
}

// An orthonormal basis around the unit vector n with no branch but a sign (Duff et al. 2017):
// to_frame turns a direction of n's frame (n = z) into the outer frame.
inline precise real3 onb_to_outer(real3 n, real3 v) {
  precise real sgn = n.z >= real(0.0) ? real(1.0) : real(-1.0);
  precise real a = real(-1.0) / (sgn + n.z);
  precise real b = n.x * n.y * a;
  precise real3 t = real3(real(1.0) + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  precise real3 bt = real3(b, sgn + n.y * n.y * a, -n.y);
  return v.x * t + v.y * bt + v.z * n;
}
inline precise real3 onb_to_inner(real3 n, real3 v) {
  precise real sgn = n.z >= real(0.0) ? real(1.0) : real(-1.0);
  precise real a = real(-1.0) / (sgn + n.z);
  precise real b = n.x * n.y * a;
  precise real3 t = real3(real(1.0) + sgn * n.x * n.x * a, sgn * b, -sgn * n.x);
  precise real3 bt = real3(b, sgn + n.y * n.y * a, -n.y);
  return real3(dot3(v, t), dot3(v, bt), dot3(v, n));
}

RTVK_KERNELS_END

#endif  // RTVK_MICROFACET_H
