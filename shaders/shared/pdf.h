// Importance sampling, the third book's ("The Rest of Your Life"): probability densities over
// directions, each with the book's two halves, `generate` (the *_random functions: a direction
// drawn from the density) and `value` (the *_pdf functions: the density of a given direction, per
// steradian). An orthonormal basis at the hit, the cosine density, the uniform sphere, the
// densities toward one light (a sphere by the cone it fills, a quad or a triangle by its area) and
// toward a list of them, and the mixture of a material's density with the lights'.
//
// The lights a render samples are the backend's table: GLSL reads `lights[]` and `light_count()`,
// which the including shader declares (shaders/render.comp), C++ a light_table passed along. The
// functions that read the table take LIGHTS_PARAM first and pass LIGHTS on.
#ifndef RTVK_PDF_H
#define RTVK_PDF_H
#include "appearance_types.h"
#include "hit_sphere.h"
#include "kernel_lang.h"
#include "lights_types.h"
#include "random.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// gpu_light's fields at the compilation's precision.
struct light_record {
  real3 a;           // sphere: center at time 0; quad: corner Q; triangle: vertex 0
  uint kind = 0;     // RTVK_LIGHT_*
  real3 u;           // sphere: velocity; quad: edge u; triangle: edge to vertex 1
  real radius = 0;   // sphere: radius
  real3 v;           // quad: edge v; triangle: edge to vertex 2
  real area = 0;     // quad, triangle: area
  real3 normal;      // quad, triangle: unit normal along cross(u, v)
  uint flags = 0;    // RTVK_LIGHT_*
  real3 emission;    // a lamp's emitted radiance, linear RGB
  real pmf = 0;      // next-event estimation's probability of drawing it (gpu_light's alias table)
  real alias_q = 1;  // the share of its slot that keeps it
  uint alias = 0;    // the lamp that takes the rest
};
// The lights a render samples (host/scene/light_sources.h makes them).
struct light_table {
  const light_record* lights = nullptr;  // by index
  uint count = 0;                        // 0: plain sampling, no light is aimed at
  // Next-event estimation's light tree over the lamps (light_tree.h; node 0 the root); null
  // elsewhere.
  const gpu::gpu_light_node* nodes = nullptr;
};
#define LIGHTS_PARAM const light_table &lights_in,
#define LIGHTS lights_in,
#define LIGHT_AT(k) lights_in.lights[k]
#define LIGHT_COUNT lights_in.count
#define LIGHT_NODE(k) lights_in.nodes[k]
#else
#define light_record gpu_light
#define LIGHTS_PARAM
#define LIGHTS
#define LIGHT_AT(k) lights[k]
#define LIGHT_COUNT light_count()
#define LIGHT_NODE(k) light_nodes[k]
#endif

const real inv_pi = real(0.31830988618379067154);

// The book's onb: three orthonormal axes, w along the given unit vector.
struct onb {
  precise real3 u;
  precise real3 v;
  precise real3 w;
};

inline onb onb_from_w(real3 n) {
  onb b;
  b.w = unit_vector(n);
  precise real3 a = abs(b.w.x) > real(0.9) ? real3(0.0, 1.0, 0.0) : real3(1.0, 0.0, 0.0);
  b.v = unit_vector(cross3(b.w, a));
  b.u = cross3(b.w, b.v);
  return b;
}

inline precise real3 onb_local(onb b, real3 a) {
  return a.x * b.u + a.y * b.v + a.z * b.w;
}

// The book's random_cosine_direction: z = cos(theta) distributed as cos(theta) / pi.
inline precise real3 random_cosine_direction(real r1, real r2) {
  precise real2 phi = turn_cos_sin(r1);
  precise real r = sqrt(r2);
  return real3(phi.x * r, phi.y * r, sqrt(max(real(0.0), real(1.0) - r2)));
}

// cosine_pdf about the unit normal n.
inline precise real cosine_pdf(real3 n, real3 direction) {
  precise real cosine = dot3(unit_vector(direction), n);
  return max(real(0.0), cosine * inv_pi);
}

inline precise real3 cosine_random(real3 n, real r1, real r2) {
  return onb_local(onb_from_w(n), random_cosine_direction(r1, r2));
}

// sphere_pdf: every direction alike.
inline precise real sphere_pdf() {
  return real(0.25) * inv_pi;
}

// 1 - cos(theta_max) of the cone a sphere of radius r fills seen from distance^2 d2 > r^2,
// without the cancellation of 1 - sqrt(1 - r^2 / d2) for a small or far sphere.
inline precise real cone_gap(real r, real d2) {
  precise real s2 = r * r / d2;
  return s2 / (real(1.0) + sqrt(max(real(0.0), real(1.0) - s2)));
}

// The book's sphere::pdf_value from `origin` at the ray's `time`: 1 / the cone's solid angle for
// a direction inside the cone, else 0; from inside the sphere, every direction alike.
inline precise real sphere_light_pdf(light_record l, real3 origin, real3 direction, real time) {
  precise real3 oc = moved_center(l.a, l.u, time) - origin;
  precise real d2 = dot3(oc, oc);
  precise real r2 = l.radius * l.radius;
  if (d2 <= r2) return sphere_pdf();
  precise real along = dot3(direction, oc);
  if (along <= real(0.0)) return real(0.0);
  // Inside the cone: the line passes within r of the center, |d x oc|^2 <= r^2 |d|^2 (not
  // cos^2 >= 1 - r^2 / d2, which cancels in float for a small or far sphere).
  precise real3 across = cross3(direction, oc);
  precise real perp2 = dot3(across, across);
  precise real reach2 = r2 * dot3(direction, direction);
  if (perp2 > reach2) return real(0.0);
  return real(0.5) * inv_pi / cone_gap(l.radius, d2);
}

// The book's sphere::random: a direction uniform in the cone (random_to_sphere in the frame whose
// w points at the center).
inline precise real3 sphere_light_random(light_record l, real3 origin, real time, real r1,
                                         real r2) {
  precise real3 oc = moved_center(l.a, l.u, time) - origin;
  precise real d2 = dot3(oc, oc);
  precise real rr = l.radius * l.radius;
  if (d2 <= rr) return random_unit_vector(r1, r2);
  precise real one_minus_z = r2 * cone_gap(l.radius, d2);
  precise real z = real(1.0) - one_minus_z;
  precise real s = sqrt(max(real(0.0), one_minus_z * (real(2.0) - one_minus_z)));
  precise real2 phi = turn_cos_sin(r1);
  return onb_local(onb_from_w(oc), real3(phi.x * s, phi.y * s, z));
}

// The book's quad::pdf_value, for a quad or a triangle: distance^2 / (|cos| area) where the ray
// from `origin` along `direction` hits the shape (t > the book's 0.001), else 0.
inline precise real flat_light_pdf(light_record l, real3 origin, real3 direction) {
  precise real facing = dot3(direction, l.normal);
  precise real len = length3(direction);
  precise real parallel = real(1e-8) * len;
  if (abs(facing) < parallel) return real(0.0);  // parallel to the plane
  precise real t = dot3(l.a - origin, l.normal) / facing;
  if (!(t > real(0.001))) return real(0.0);
  // Where the hit lies in the edges' coordinates (the book's alpha and beta): w = n / |u x v|.
  precise real3 rel = origin + t * direction - l.a;
  precise real span = l.kind == uint(RTVK_LIGHT_QUAD) ? l.area : real(2.0) * l.area;
  precise real alpha = dot3(l.normal, cross3(rel, l.v)) / span;
  precise real beta = dot3(l.normal, cross3(l.u, rel)) / span;
  precise real both = alpha + beta;
  bool inside =
      l.kind == uint(RTVK_LIGHT_QUAD)
          ? alpha >= real(0.0) && alpha <= real(1.0) && beta >= real(0.0) && beta <= real(1.0)
          : alpha >= real(0.0) && beta >= real(0.0) && both <= real(1.0);
  if (!inside) return real(0.0);
  // t^2 |d|^2 / (|d . n| / |d| area)
  return t * t * len * len * len / (abs(facing) * l.area);
}

// The book's quad::random, for a quad or a triangle: toward a point uniform on its area (a
// triangle's by the square-root warp).
inline precise real3 flat_light_random(light_record l, real3 origin, real r1, real r2) {
  if (l.kind == uint(RTVK_LIGHT_QUAD)) return l.a + r1 * l.u + r2 * l.v - origin;
  precise real s = sqrt(r1);
  return l.a + (s * (real(1.0) - r2)) * l.u + (s * r2) * l.v - origin;
}

inline precise real light_pdf(light_record l, real3 origin, real3 direction, real time) {
  return l.kind == uint(RTVK_LIGHT_SPHERE) ? sphere_light_pdf(l, origin, direction, time)
                                           : flat_light_pdf(l, origin, direction);
}

inline precise real3 light_random(light_record l, real3 origin, real time, real r1, real r2) {
  return l.kind == uint(RTVK_LIGHT_SPHERE) ? sphere_light_random(l, origin, time, r1, r2)
                                           : flat_light_random(l, origin, r1, r2);
}

// The density of a direction light l's own sampler drew (light_random), from the book's formulas
// at the sampled point, without testing again whether it hits l: in float a direction drawn at
// l's edge can test outside it, and its weight would then be thousands of times too large (a
// lamp 200 radii away drew 114 times too bright on lavapipe). Exact math gives light_pdf.
inline precise real light_sampled_pdf(light_record l, real3 origin, real3 direction, real time) {
  if (l.kind == uint(RTVK_LIGHT_SPHERE)) {
    precise real3 oc = moved_center(l.a, l.u, time) - origin;
    precise real d2 = dot3(oc, oc);
    precise real r2 = l.radius * l.radius;
    if (d2 <= r2) return sphere_pdf();
    return real(0.5) * inv_pi / cone_gap(l.radius, d2);
  }
  precise real facing = dot3(direction, l.normal);
  if (facing == real(0.0)) return real(0.0);  // in the light's plane: it cannot be hit
  precise real len = length3(direction);      // the distance: the sampler aims at a point
  return len * len * len / (abs(facing) * l.area);
}

// The book's hittable_list::pdf_value: the mean of the lights' densities. Light `own` (none when
// LIGHT_COUNT) drew the direction, and its density is `own_pdf` (light_sampled_pdf).
inline precise real light_list_pdf(LIGHTS_PARAM real3 origin, real3 direction, real time, uint own,
                                   real own_pdf) {
  precise real sum = real(0.0);
  for (uint k = 0u; k < LIGHT_COUNT; ++k)
    sum += k == own ? own_pdf : light_pdf(LIGHT_AT(k), origin, direction, time);
  return sum / real(LIGHT_COUNT);
}

// The book's hittable_list::random: toward a light picked uniformly; `own` is the light and
// `own_pdf` its density for the direction.
inline precise real3 light_list_random(LIGHTS_PARAM real3 origin, real time, random_stream s,
                                       OUT(uint) own, precise OUT(real) own_pdf) {
  precise real pick = real(rnd(s, dim_light_pick)) * real(LIGHT_COUNT);
  own = min(uint(pick), LIGHT_COUNT - 1u);
  precise real3 direction = light_random(LIGHT_AT(own), origin, time, real(rnd(s, dim_light_a)),
                                         real(rnd(s, dim_light_b)));
  own_pdf = light_sampled_pdf(LIGHT_AT(own), origin, direction, time);
  return direction;
}

// A scattering material's own density (the book's srec.pdf_ptr and scattering_pdf, which are the
// same for both kinds here): the cosine about the normal for lambertian, every direction for
// isotropic.
inline precise real material_pdf(uint type, real3 normal, real3 direction) {
  return type == uint(RTVK_MATERIAL_ISOTROPIC) ? sphere_pdf() : cosine_pdf(normal, direction);
}

// The book's ray_color with lights: lambertian and isotropic scatter along the mixture of their
// own density and the lights' (half each), weighted by scattering_pdf / mixture_pdf; the others
// scatter as without lights (the book's skip_pdf). False when absorbed (a direction the material
// does not scatter into: weight 0).
inline bool scatter_mixture(LIGHTS_PARAM uint type, real3 albedo, ray r_in, hit_record rec,
                            random_stream s, precise OUT(real3) attenuation,
                            precise OUT(ray) scattered) {
  bool isotropic = type == uint(RTVK_MATERIAL_ISOTROPIC);
  // Leaves from the side of the surface the ray came from (a medium's point has no side).
  precise real3 origin = isotropic ? rec.p : rec.p + rec.offset * rec.normal;
  precise real3 direction;
  uint own = LIGHT_COUNT;  // the light that drew the direction: none
  precise real own_pdf = real(0.0);
  if (real(rnd(s, dim_mixture)) < real(0.5))
    direction = light_list_random(LIGHTS origin, r_in.time, s, own, own_pdf);
  else if (isotropic)
    direction = random_unit_vector(real(rnd(s, dim_direction_a)), real(rnd(s, dim_direction_b)));
  else
    direction =
        cosine_random(rec.normal, real(rnd(s, dim_direction_a)), real(rnd(s, dim_direction_b)));
  scattered = ray(origin, direction, r_in.time);
  attenuation = real3(0.0);
  precise real scattering = material_pdf(type, rec.normal, direction);
  precise real mixture =
      real(0.5) * scattering +
      real(0.5) * light_list_pdf(LIGHTS origin, direction, r_in.time, own, own_pdf);
  if (!(scattering > real(0.0)) || !(mixture > real(0.0))) return false;
  attenuation = albedo * (scattering / mixture);
  return true;
}

RTVK_KERNELS_END

#endif  // RTVK_PDF_H
