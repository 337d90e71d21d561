// ray_color's loop, a bounce per trip: the steps are the shared kernels' (ray_color.h), which
// the CPU runs too (host/cpu/shading.cpp); what is the GPU's own is the world search (world.glsl)
// and the loop budget. Expects `materials` (gpu_material[]), `pc` (render_push), `lights` and
// light_count() (pdf.h), `environment_texels` and `environment_table` (environment.h) declared by
// the including shader.
#ifndef RTVK_SHADING_GLSL
#define RTVK_SHADING_GLSL
#include "environment.h"
#include "medium.h"
#include "nee_pbr.h"
#include "pbr_shading.h"
#include "ray_color.h"
#include "texture.h"
#include "world.glsl"

// Whether some material has a texture, whether the scene has media: without, their code is
// compiled out (on lavapipe it alone nearly halved book-final's speed).
layout(constant_id = RTVK_SPEC_TEXTURES) const bool any_textures = false;
layout(constant_id = RTVK_SPEC_MEDIA) const bool any_media = false;
// Whether every hit blocks a shadow ray (no see-through material, no media): its search then
// ends at the first hit (world.glsl's first_hit_ends).
layout(constant_id = RTVK_SPEC_OPAQUE_SHADOWS) const bool opaque_shadows = false;
// Whether some material is PBR: without, pbr_shading.h's code is compiled out (the books' scenes
// run the shader they ran before it).
layout(constant_id = RTVK_SPEC_PBR) const bool any_pbr = false;

// Medium k as the shared kernels take it.
medium_geometry medium_at(uint k) {
  medium_geometry m;
  m.to_local_x = media[k].to_local_x.xyz;
  m.to_local_y = media[k].to_local_y.xyz;
  m.to_local_z = media[k].to_local_z.xyz;
  m.to_local_offset = vec3(media[k].to_local_x.w, media[k].to_local_y.w, media[k].to_local_z.w);
  m.shape = media[k].shape;
  m.lo = media[k].lo;
  m.hi = media[k].hi;
  m.neg_inv_density = media[k].neg_inv_density;
  m.material = media[k].material;
  m.index = media[k].index;
  return m;
}

const float max_float = 3.402823466e+38;  // stands in for the host's infinity as t_max

// One trip through ray_color's loop; render.comp holds the loop itself, over all of an
// invocation's samples, so a lane whose path ended starts its next sample at once. Traces p.r
// and either ends the path, its color in `c`, or scatters it for the next trip. Over the loop
// budget the path ends black and `iterations` tells the caller.
bool ray_color_step(precise inout path_state p, precise out vec3 c, inout uint iterations,
                    inout uint rays) {
  c = vec3(0.0);
  // A step counts trace_cost iterations (1 until a driver's loop limit cut an invocation short
  // all the same: the loops rtvk does not count, such as the samples' own, then weigh more).
  iterations += pc.trace_cost;
  if (iterations > pc.loop_budget) return true;
  // Under next-event estimation a pending shadow ray takes a trip of its own, through the same
  // world search as the path's rays (one copy of the traversal in the shader).
  bool shadow = nee && p.shadow_reach > 0.0;
  if (!shadow && path_ends_unlit(p, pc.max_depth)) {
    c = p.radiance;
    return true;
  }
  ++rays;
  hit_record rec;
  first_hit_ends = shadow && opaque_shadows;
  bool hit = hit_world(shadow ? p.shadow : p.r, t_min, shadow ? p.shadow_reach : max_float, rec,
                       iterations);
  if (shadow) {
    // A medium that scatters the shadow ray before its end blocks it (nee.h's shadow_blocked).
    if (any_media) {
      random_stream s = shadow_stream(p);
      precise float t_end = hit ? rec.t : p.shadow_reach;
      hit_record scatter_point;
      for (uint k = 0u; k < pc.medium_count; ++k) {
        ++iterations;
        if (hit_medium(medium_at(k), p.shadow, t_min, t_end,
                       medium_random(s, k, dim_shadow_medium), scatter_point)) {
          shadow_blocked(p);
          return false;
        }
      }
    }
    if (!hit) {
      shadow_unblocked(p);
      return false;
    }
    gpu_material o = materials[rec.material];
    precise float alpha = (o.flags & RTVK_MATERIAL_SEE_THROUGH) == 0u ? 1.0
                          : any_textures ? surface_alpha(o.opacity, o.texture, rec)
                                         : o.opacity * rec.color.w;
    shadow_meets(p, rec, o.type, o.flags, alpha, o.alpha_cutoff);
    return false;
  }
  // The media after the world, within its hit (host/cpu/shading.cpp's ray_color does the same).
  if (any_media) {
    random_stream s = at_bounce(p.s, p.depth + 1u);
    for (uint k = 0u; k < pc.medium_count; ++k) {
      ++iterations;
      if (hit_medium(medium_at(k), p.r, t_min, hit ? rec.t : max_float, medium_random(s, k, dim_medium), rec))
        hit = true;
    }
  }
  if (!hit) {
    iterations += NEE_PUNCTUAL_COUNT;  // the suns' densities where the path escapes (nee.h)
    if (iterations > pc.loop_budget) return true;
    if (nee)
      c = path_missed_nee(p, pc.sky_horizon, pc.sky_zenith);
    else if (any_environment && path_sees_environment(p, environment_visible()))
      c = path_missed_into(p, environment_radiance(p.r.direction));
    else
      c = path_missed(p, pc.sky_horizon, pc.sky_zenith);
    return true;
  }
  gpu_material m = materials[rec.material];
  bool pbr = any_pbr && m.type == RTVK_MATERIAL_PBR;
  // Absorbed on the way through a PBR volume, before anything else at its surface.
  if (pbr) p.throughput *= pbr_volume_transmittance(pbrs[m.pbr], rec, p.r);
  // A surface that lets this ray through: the path goes on beyond it, no bounce counted (as
  // host/cpu/shading.cpp's ray_color).
  if ((m.flags & RTVK_MATERIAL_SEE_THROUGH) != 0u) {
    precise float alpha = any_textures ? surface_alpha(m.opacity, m.texture, rec)
                                       : m.opacity * rec.color.w;
    if (path_passes(p, rec, m.type, m.flags, alpha, m.alpha_cutoff)) return false;
  }
  if ((m.flags & RTVK_MATERIAL_EMISSIVE) != 0u) {
    precise vec3 emitted =
        m.emission *
        (any_textures ? emission_color(m.emission_texture, rec) : vec3(1.0));
    path_emits(p, emitted);
  }
  // Every multiply precise (ShaderPrecision): times 1 where the hit has no vertex colors, exact.
  precise vec3 albedo =
      (any_textures ? material_color(m.albedo, m.texture, rec) : m.albedo) * rec.color.xyz;
  // The lights' densities loop over every light (pdf.h): lavapipe counts those trips too. Next-event
  // estimation's light tree counts its own (light_tree_trips, added after the step).
  if (!nee) iterations += light_count();
  // Next-event estimation's draw toward the environment: its two binary searches.
  if (nee && any_environment) iterations += environment_sample_trips();
  if (pbr) {
    precise vec3 wo = -unit_vector(p.r.direction);
    gpu_pbr q = pbrs[m.pbr];
    pbr_texels t = any_textures ? pbr_texels_at(q, rec) : pbr_no_texels();
    iterations += uint(pbr_map_count);  // pbr_texels_at's loop: lavapipe counts its trips
    if (nee) {
      bool ended = path_hit_pbr_nee(p, rec, pbr_surface_from(q, albedo, rec, t),
                                    pbr_shading_normal(q, rec, t, wo),
                                    pbr_coat_normal(q, rec, t, wo), c);
      iterations += light_tree_trips;
      light_tree_trips = 0u;
      return ended;
    }
    return path_hit_pbr(p, rec, pbr_surface_from(q, albedo, rec, t), pbr_shading_normal(q, rec, t, wo),
                        pbr_coat_normal(q, rec, t, wo), c);
  }
  if (nee) {
    bool ended = path_hit_nee(p, rec, m.type, m.flags, albedo, m.fuzz, m.ir, c);
    iterations += light_tree_trips;  // the light tree's draw and the lamp hit's point query
    light_tree_trips = 0u;
    return ended;
  }
  return path_hit(p, rec, m.type, m.flags, albedo, m.fuzz, m.ir, c);
}

#endif
