// Next-event estimation with multiple importance sampling (Veach's thesis, chapter 9; pbrt-v4's
// PathIntegrator): at every vertex whose BSDF is not a delta, one light is drawn, its sample
// weighted by the BSDF there and sent along a shadow ray; the BSDF's own sample goes on as the
// path, and when it hits a lamp, the lamp's light is weighted too. The power heuristic splits each
// light path between the two ways that could have drawn it, so the sum is unbiased and each
// light is found by the way that draws it best: small lamps by the light sample, glossy
// reflections of large ones by the BSDF.
//
// The lights drawn are the scene's lamps, its punctual lights (punctual.h: point, spot,
// directional, suns) and its environment map (environment.h, by its own importance sampler),
// each kind present drawn alike (a third each where all are); among the punctual lights, each
// alike. The lamps are pdf.h's records with RTVK_LIGHT_EMITS (the first
// LIGHT_COUNT of the table in this mode), each chosen through the light tree (light_tree.h;
// host/scene/ light_tree.cpp builds it) by its importance seen from the vertex: its power, distance
// and orientation, in the tree's depth of steps whatever the number of lamps. A lamp whose emission
// varies over it (RTVK_LIGHT_UNEVEN) is never drawn: its light comes whole from the paths that hit
// it.
//
// The shadow ray is not traced here: the step leaves it in the path state (path_state::shadow) and
// each backend traces it before the path goes on (host/cpu/shading.cpp at once; the GPU in a trip
// of its own through the one world search, shaders/shading.glsl).
#ifndef RTVK_NEE_H
#define RTVK_NEE_H
#include "environment.h"
#include "kernel_lang.h"
#include "light_sample.h"
#include "light_tree.h"
#include "pdf.h"
#include "punctual.h"
#include "random.h"
#include "ray_color.h"

// The punctual lights next-event estimation draws: the table's (a GPU shader defines it first, to
// compile them out where the scene has none).
#ifndef NEE_PUNCTUAL_COUNT
#define NEE_PUNCTUAL_COUNT PUNCTUAL_COUNT
#endif
// Whether it draws the environment map: where the scene has one (a GPU shader defines it first,
// from its specialization constant).
#ifndef NEE_ENVIRONMENT
#define NEE_ENVIRONMENT (env_in.table != nullptr)
#endif
// The tables of the lights next-event estimation draws: the lamps, the punctual lights and the
// environment (C++: three parameters; GLSL: none, the shader's buffers).
#define NEE_PARAM LIGHTS_PARAM PUNCTUAL_PARAM ENV_PARAM
#define NEE_LIGHTS LIGHTS PUNCTUALS ENV
#ifdef __cplusplus
#define NEE_PARAM_ONLY \
  const light_table &lights_in, const punctual_table &punctual_in, const environment_table &env_in
#define NEE_LIGHTS_ONLY lights_in, punctual_in, env_in
#else
#define NEE_PARAM_ONLY
#define NEE_LIGHTS_ONLY
#endif

RTVK_KERNELS_BEGIN

// Random dimensions of a vertex's light sample (at_bounce's stream): the light's choice and the
// point on it are pdf.h's dim_light_pick, dim_light_a and dim_light_b, which the mixture of the
// third book (the other mode) uses for the same purpose.
const uint dim_roulette = 13u;      // bounce >= 1: Russian roulette's draw
const uint dim_shadow_alpha = 14u;  // bounce >= 1: a blended surface on the shadow ray lets it by

// The shadow ray stops this far short of the sampled point (a fraction of the distance), so that
// the lamp's own surface does not block its light.
const real shadow_gap = real(1e-3);

// Veach's power heuristic (beta 2) for one sample of each strategy: the weight of the strategy
// whose density is `a` against the one whose density is `b` (both per steradian, each times its
// choice probability). An infinite `a` takes all.
inline precise real power_heuristic(real a, real b) {
  if (!(a < real(3.0e38))) return real(1.0);
  precise real a2 = a * a;
  precise real b2 = b * b;
  precise real sum = a2 + b2;
  return sum > real(0.0) ? a2 / sum : real(0.0);
}

// Lamp l seen from `origin`: a point drawn on it (pdf.h's light_random, the book's samplers),
// with its density per steradian and the radiance it sends toward origin (none from a one-sided
// lamp's back, none from an uneven lamp).
inline light_sample lamp_sample(light_record l, real3 origin, real time, real r1, real r2) {
  light_sample ls = no_light_sample();
  if ((l.flags & RTVK_LIGHT_UNEVEN) != 0u) return ls;
  precise real3 direction = light_random(l, origin, time, r1, r2);
  precise real len = length3(direction);
  if (!(len > real(0.0))) return ls;
  ls.wi = direction / len;
  ls.distance = l.kind == uint(RTVK_LIGHT_SPHERE) ? lamp_distance(l, origin, ls.wi, time) : len;
  if (!(ls.distance > real(0.0))) return ls;
  bool back = l.kind != uint(RTVK_LIGHT_SPHERE) && dot3(ls.wi, l.normal) > real(0.0);
  if (back && (l.flags & RTVK_LIGHT_ONE_SIDED) != 0u) return ls;
  ls.pdf = light_sampled_pdf(l, origin, direction, time);
  ls.radiance = l.emission;
  return ls;
}

// The probabilities that nee_draw_at draws from the lamps, the punctual lights and the environment:
// each kind present alike.
inline precise real3 nee_kinds(NEE_PARAM_ONLY) {
  real lamps = LIGHT_COUNT > 0u ? real(1.0) : real(0.0);
  real punctual = NEE_PUNCTUAL_COUNT > 0u ? real(1.0) : real(0.0);
  real environment = NEE_ENVIRONMENT ? real(1.0) : real(0.0);
  precise real n = lamps + punctual + environment;
  if (!(n > real(0.0))) return real3(0.0);
  return real3(lamps, punctual, environment) / n;
}

// The lamp drawn by one uniform number u in [0, 1) for the vertex at `origin` with normal n (zero:
// a medium's): through the light tree where the table has one (light_tree.h: by each lamp's
// importance seen from there), else by the alias table (gpu_light::pmf, alias_q, alias: by power
// alone). Its probability in `pmf`; 0 where none can be drawn.
inline uint nee_lamp_pick(LIGHTS_PARAM real3 origin, real3 n, real u, precise OUT(real) pmf) {
  if (LIGHT_TREE_PRESENT) return light_tree_draw(LIGHTS origin, n, u, pmf);
  precise real pick = u * real(LIGHT_COUNT);
  uint k = min(uint(pick), LIGHT_COUNT - 1u);
  precise real within = pick - real(k);
  if (!(within < LIGHT_AT(k).alias_q)) k = LIGHT_AT(k).alias;
  pmf = LIGHT_AT(k).pmf;
  return k;
}

// A light drawn for the vertex at `origin` (unit normal n; zero in a medium) from stream s
// (Owen-scrambled Sobol numbers): its kind, then a lamp (nee_lamp_pick) or a punctual light alike
// (one number: the kind by where it falls, the rest scaled back to [0, 1) for the choice within),
// then a point or direction on it (two numbers; the environment's by its sampler); choice: the
// probability of having drawn that light. No sample (pdf 0) without lights to draw.
inline light_sample nee_draw_at(NEE_PARAM real3 origin, real3 n, real time, random_stream s,
                                precise OUT(real) choice) {
  choice = real(0.0);
  precise real3 kinds = nee_kinds(NEE_LIGHTS_ONLY);
  // Low-discrepancy numbers (sobol.h): the pick in one dimension, the point on the light a pair
  // (a (0, 2)-net over a pixel's samples), so that its samples cover each light evenly.
  precise real u = real(sobol_rnd(s, dim_light_pick));
  precise real2 ab = sobol_rnd2(s, dim_light_a);
  real a = ab.x;
  real b = ab.y;
  if (u < kinds.x) {
    precise real pmf;
    uint k = nee_lamp_pick(LIGHTS origin, n, min(u / kinds.x, real(0.99999994)), pmf);
    choice = kinds.x * pmf;
    if (!(choice > real(0.0))) return no_light_sample();
    return lamp_sample(LIGHT_AT(k), origin, time, a, b);
  }
  precise real past = u - kinds.x;
  if (past < kinds.y) {
    precise real pick = (past / kinds.y) * real(NEE_PUNCTUAL_COUNT);
    uint k = min(uint(pick), NEE_PUNCTUAL_COUNT - 1u);
    choice = kinds.y / real(NEE_PUNCTUAL_COUNT);
    return punctual_sample(PUNCTUALS k, origin, real2(a, b));
  }
  if (!(kinds.z > real(0.0))) return no_light_sample();
  choice = kinds.z;
  return environment_sample(ENV real2(a, b));
}

// The density (per steradian, times the lamp's pmf) with which nee_draw_at at `origin` would have
// drawn the point that the ray along unit direction d hit at distance t_hit: that of the lamp
// whose surface lies there (its own test of the ray agreeing within a thousandth), 0 where none
// does (a lamp not drawn: uneven, in a group, or no lamp at all).
inline precise real nee_lamp_pdf(LIGHTS_PARAM real3 origin, real3 d, real time, real t_hit) {
  for (uint k = 0u; k < LIGHT_COUNT; ++k) {
    light_record l = LIGHT_AT(k);
    if (!(l.pmf > real(0.0))) continue;
    precise real t = lamp_distance(l, origin, d, time);
    precise real off = abs(t - t_hit);
    precise real tolerance = real(1e-3) * t_hit + real(1e-6);
    if (off > tolerance) continue;
    return light_pdf(l, origin, d, time) * l.pmf;
  }
  return real(0.0);
}

// The density with which nee_draw_at at `at` (normal n) would have drawn the point that the ray
// from `origin` along unit direction d hit at distance t_hit (origin: where the path left the
// vertex, a hair from `at`): the tree's probability of the lamp lying there (light_tree_find,
// then its trail) times that lamp's density per steradian; without a tree, nee_lamp_pdf's.
inline precise real nee_lamp_pdf_at(LIGHTS_PARAM real3 at, real3 n, real3 origin, real3 d,
                                    real time, real t_hit) {
  if (!LIGHT_TREE_PRESENT) return nee_lamp_pdf(LIGHTS origin, d, time, t_hit);
  uint leaf;
  if (!light_tree_find(LIGHTS origin, d, time, t_hit, leaf)) return real(0.0);
  light_node nd = LIGHT_NODE(leaf);
  precise real pmf = light_tree_trail_pmf(LIGHTS at, n, nd.second);
  if (!(pmf > real(0.0))) return real(0.0);
  return light_pdf(LIGHT_AT(nd.lamp), origin, d, time) * pmf;
}

// The light sample ls (chosen with probability `choice`) weighed by the BSDF at the vertex: f is
// the BSDF times |cos| toward ls.wi, bsdf_pdf the density with which the BSDF's own sample would
// have drawn ls.wi. Leaves the shadow ray in p (from `origin`, short of the light by shadow_gap)
// with what it adds when nothing blocks it; nothing where either is 0.
inline void nee_queue(precise INOUT(path_state) p, real3 origin, light_sample ls, real choice,
                      real3 f, real bsdf_pdf) {
  if (!(ls.pdf > real(0.0)) || !(choice > real(0.0))) return;
  // The path's last vertex (its BSDF ray will not be traced) takes no light sample: the bounce
  // limit cuts the light it gathers as the other modes' paths are cut, and a light sample weighed
  // against a BSDF ray never traced would leave out that ray's share.
  if (p.depth + 1u >= p.max_depth) return;
  precise real light_pdf_ = choice * ls.pdf;
  precise real w = ls.delta ? real(1.0) : power_heuristic(light_pdf_, bsdf_pdf);
  precise real3 add = p.throughput * f * ls.radiance * (w / light_pdf_);
  precise real total = add.x + add.y + add.z;
  if (!(total > real(0.0))) return;
  p.shadow = ray(origin, ls.wi, p.r.time);
  precise real short_of = ls.distance * (real(1.0) - shadow_gap);
  p.shadow_reach = ls.distance < light_at_infinity ? short_of : light_at_infinity;
  p.shadow_radiance = add;
  p.shadow_passes = 0u;
}

// p.r hit a lamp at `point`: the weight of its light against the light sample that could have
// drawn the same point from the vertex the path left (p.mis_origin; p.r's own origin is beyond the
// see-through surfaces it passed since). None after a delta or from the camera: p.mis_pdf 0, the
// path's light whole.
inline precise real nee_hit_weight(NEE_PARAM path_state p, real3 point) {
  if (!(p.mis_pdf > real(0.0))) return real(1.0);
  precise real3 d = unit_vector(p.r.direction);
  precise real distance = length3(point - p.mis_origin);
  precise real lamps = nee_kinds(NEE_LIGHTS_ONLY).x;
  precise real light =
      lamps * nee_lamp_pdf_at(LIGHTS p.mis_at, p.mis_normal, p.mis_origin, d, p.r.time, distance);
  return power_heuristic(p.mis_pdf, light);
}

// p.r escaped: the sky or the environment map (as path_missed and path_missed_into), and the
// suns' disks it points into. The map and the suns are weighed against the light sample that could
// have drawn the same direction (each one's density times its choice); the sky, which no light
// sample draws, gives its light whole, as does all of it after a delta or from the camera.
inline precise real3 path_missed_nee(NEE_PARAM path_state p, real3 horizon, real3 zenith) {
  precise real3 kinds = nee_kinds(NEE_LIGHTS_ONLY);
  bool mixed = p.mis_pdf > real(0.0);
  precise real3 c;
  if (NEE_ENVIRONMENT && path_sees_environment(p, environment_visible(ENV_ALONE))) {
    precise real w = mixed
                         ? power_heuristic(p.mis_pdf, kinds.z * environment_pdf(ENV p.r.direction))
                         : real(1.0);
    c = path_missed_into(p, environment_radiance(ENV p.r.direction) * w);
  } else {
    c = path_missed(p, horizon, zenith);
  }
  if (NEE_PUNCTUAL_COUNT == 0u) return c;
  precise real3 sun = real3(0.0);
  precise real density = real(0.0);
  for (uint k = 0u; k < NEE_PUNCTUAL_COUNT; ++k) {
    precise real pdf = sun_pdf(PUNCTUALS k, p.r.direction);
    if (!(pdf > real(0.0))) continue;
    sun += sun_disk_radiance(PUNCTUAL_AT(k));
    density += pdf;
  }
  precise real choice = kinds.y / real(NEE_PUNCTUAL_COUNT);
  precise real w = mixed ? power_heuristic(p.mis_pdf, choice * density) : real(1.0);
  return c + p.throughput * sun * w;
}

// Russian roulette (pbrt-v4's): past the third bounce a path goes on with the probability of its
// throughput's largest channel (at most 0.95), its throughput divided by it, so that the expected
// value is unchanged. False: the path ends here.
inline bool nee_roulette(precise INOUT(path_state) p, random_stream s) {
  if (p.depth < 3u) return true;
  precise real q = min(real(0.95), max(p.throughput.x, max(p.throughput.y, p.throughput.z)));
  if (!(real(rnd(s, dim_roulette)) < q)) return false;
  p.throughput = p.throughput / q;
  return true;
}

// The path ends after its pending shadow ray, if any (path_ends_unlit sees no direction): the
// steps below end a path this way rather than by returning true, so that the light sample of its
// last vertex still counts.
inline void nee_end(precise INOUT(path_state) p) {
  p.r.direction = real3(0.0);
}

// p.r hit `rec` under next-event estimation; as path_hit (ray_color.h) otherwise. A lamp adds its
// light weighed against the light sample (nee_hit_weight); lambertian and isotropic surfaces take
// a light sample (their BSDF albedo / pi times the cosine, or albedo / 4 pi) and scatter as the
// first two books do, their density kept for the next hit's weight; the others scatter as
// path_hit has them, and whatever lamp their ray hits gives its light whole.
inline bool path_hit_nee(NEE_PARAM precise INOUT(path_state) p, hit_record rec, uint type,
                         uint flags, real3 albedo, real fuzz, real ir, precise OUT(real3) c) {
  c = p.radiance;
  if (type == RTVK_MATERIAL_DIFFUSE_LIGHT) {
    bool dark = (flags & RTVK_MATERIAL_ONE_SIDED) != 0u && !rec.front_face;
    if (!dark) c = p.radiance + p.throughput * albedo * nee_hit_weight(NEE_LIGHTS p, rec.p);
    return true;
  }
  random_stream s = at_bounce(p.s, p.depth + 1u);
  bool diffuse = type == RTVK_MATERIAL_LAMBERTIAN || type == RTVK_MATERIAL_ISOTROPIC;
  if (!diffuse) {
    p.mis_pdf = real(0.0);
    if (path_hit(LIGHTS p, rec, type, flags, albedo, fuzz, ir, c)) return true;
  } else {
    bool isotropic = type == RTVK_MATERIAL_ISOTROPIC;
    precise real3 origin = isotropic ? rec.p : rec.p + rec.offset * rec.normal;
    precise real choice;
    precise real3 normal = isotropic ? real3(0.0) : rec.normal;
    light_sample ls = nee_draw_at(NEE_LIGHTS origin, normal, p.r.time, s, choice);
    precise real bsdf_pdf = material_pdf(type, rec.normal, ls.wi);
    precise real3 f = albedo * bsdf_pdf;  // albedo / pi times the cosine, or albedo / 4 pi
    nee_queue(p, isotropic ? rec.p : scatter_origin(rec, ls.wi), ls, choice, f, bsdf_pdf);
    precise real3 attenuation;
    if (!scatter(type, albedo, fuzz, ir, p.r, rec, s, attenuation, p.r)) {
      nee_end(p);
      return false;
    }
    p.mis_pdf = material_pdf(type, rec.normal, p.r.direction);
    p.mis_origin = p.r.origin;
    p.mis_at = origin;
    p.mis_normal = normal;
    p.throughput *= attenuation;
    ++p.depth;
  }
  if (!nee_roulette(p, s)) nee_end(p);
  return false;
}

// The pending shadow ray met nothing before its reach: its light is the path's.
inline void shadow_unblocked(precise INOUT(path_state) p) {
  p.radiance += p.shadow_radiance;
  p.shadow_reach = real(0.0);
}

// The stream of the pending shadow ray's numbers: its vertex's bounce, and above bit 16 the
// surfaces it passed, so that each stretch of it draws its own.
inline random_stream shadow_stream(path_state p) {
  return at_bounce(p.s, (p.depth + 1u) | (p.shadow_passes << 16u));
}

// The pending shadow ray is blocked: by an opaque surface, or by a medium that scattered it before
// its end (medium.h's hit_medium with dim_shadow_medium: the chance that none does is the media's
// transmittance, so counting the light only then is unbiased).
inline void shadow_blocked(precise INOUT(path_state) p) {
  p.shadow_reach = real(0.0);
}

// The pending shadow ray hit `rec` (at distance rec.t along its unit direction), on a surface
// with these flags and alpha (surface_alpha): a surface that lets it by as path_passes lets a
// path by (its own draw for a blend) moves it beyond; any other blocks it (glass included: light
// through glass comes by the paths that cross it).
inline void shadow_meets(precise INOUT(path_state) p, hit_record rec, uint type, uint flags,
                         real alpha, real cutoff) {
  random_stream s = shadow_stream(p);
  real u = (flags & RTVK_MATERIAL_ALPHA_BLEND) != 0u ? real(rnd(s, dim_shadow_alpha)) : real(0.0);
  bool by = (flags & RTVK_MATERIAL_SEE_THROUGH) != 0u && p.shadow_passes < max_passes &&
            !surface_counts(type, flags, rec.front_face, alpha, cutoff, u);
  if (!by) {
    shadow_blocked(p);
    return;
  }
  p.shadow.origin = scatter_origin(rec, p.shadow.direction);
  precise real left = p.shadow_reach - rec.t;
  if (p.shadow_reach < light_at_infinity) p.shadow_reach = left;
  ++p.shadow_passes;
  if (!(p.shadow_reach > real(0.0))) shadow_unblocked(p);
}

RTVK_KERNELS_END

#endif  // RTVK_NEE_H
