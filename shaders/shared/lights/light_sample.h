// What next-event estimation asks of every light: seen from a shading point, one direction toward
// it with the radiance arriving along that direction and the density it was drawn with. Area
// lights (pdf.h's light records), the environment (environment.h) and the punctual lights
// (punctual.h) each fill one; the path step (nee.h) weighs it against the BSDF's own sample.
#ifndef RTVK_LIGHT_SAMPLE_H
#define RTVK_LIGHT_SAMPLE_H
#include "kernel_lang.h"

RTVK_KERNELS_BEGIN

// A light's distance where it has none (the environment, a directional light): a shadow ray to
// it tests every hit (the GPU's float max, which the CPU's double holds too).
const real light_at_infinity = real(3.402823466e+38);

struct light_sample {
  precise real3 wi;        // unit direction from the shading point toward the light
  precise real distance;   // to the sampled point, scene units (the shadow ray's reach);
                           // light_at_infinity for the environment and directional lights
  precise real3 radiance;  // arriving along -wi, linear RGB: radiance for lights a ray can hit,
                           // irradiance (normal to wi) for a delta light
  precise real pdf;        // solid-angle density of wi, per steradian (without the choice of
                           // this light among the others); 0: no sample (nothing to add)
  bool delta;              // a point, spot or directional light without size: no BSDF sample
                           // can find it, so it takes no multiple-importance weight
};

inline light_sample no_light_sample() {
  light_sample ls;
  ls.wi = real3(0.0, 0.0, 1.0);
  ls.distance = real(0.0);
  ls.radiance = real3(0.0);
  ls.pdf = real(0.0);
  ls.delta = false;
  return ls;
}

RTVK_KERNELS_END

#endif  // RTVK_LIGHT_SAMPLE_H
