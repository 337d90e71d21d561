#include "light_sources.h"
#include "object_group.h"
#include "punctual.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace rtvk {
namespace {

bool is_lamp(const scene& s, int material) {
  return s.materials[std::size_t(material)].m.type == material_type::diffuse_light;
}

light_record sphere_light(const sphere& sp) {
  light_record l;
  l.kind = RTVK_LIGHT_SPHERE;
  l.a = sp.center;
  l.u = sp.velocity();
  l.radius = sp.radius;
  return l;
}

// A quad (corner, edges) or a triangle (vertex 0, edges to 1 and 2).
light_record flat_light(std::uint32_t kind, const point3& a, const vec3& u, const vec3& v) {
  light_record l;
  l.kind = kind;
  l.a = a;
  l.u = u;
  l.v = v;
  const vec3 n = glm::cross(u, v);
  const double twice = glm::length(n);
  l.area = kind == RTVK_LIGHT_QUAD ? twice : twice / 2;
  l.normal = n / twice;
  return l;
}

// Light l as a lamp of material `index` (what next-event estimation reads): its emission, its
// sides, and whether that emission varies over it (a texture, or vertex colors where `colored`).
light_record as_lamp(light_record l, const scene& s, int index, bool colored) {
  const material& m = s.materials[std::size_t(index)].m;
  l.flags = RTVK_LIGHT_EMITS;
  if (m.one_sided) l.flags |= RTVK_LIGHT_ONE_SIDED;
  if (m.texture >= 0 || colored) l.flags |= RTVK_LIGHT_UNEVEN;
  l.emission = m.albedo;
  return l;
}

bool has_colors(const scene& s, const triangle& t) {
  return t.shading >= 0 && s.shading[std::size_t(t.shading)].has_color;
}

// Vose's alias table over the lamps (the first `count` of `lights`), by power: each gets its
// probability (pmf) and its slot's split (alias_q, alias), which nee_draw_at reads where the table
// has no light tree.
void build_alias_table(std::vector<light_record>& lights, std::size_t count) {
  double total = 0;
  for (std::size_t k = 0; k < count; ++k) total += lamp_power(lights[k]);
  if (!(total > 0)) return;  // nothing to draw: every pmf stays 0
  std::vector<double> scaled(count);
  std::vector<std::size_t> small, large;
  for (std::size_t k = 0; k < count; ++k) {
    lights[k].pmf = lamp_power(lights[k]) / total;
    scaled[k] = lights[k].pmf * double(count);
    (scaled[k] < 1 ? small : large).push_back(k);
  }
  while (!small.empty() && !large.empty()) {
    const std::size_t s = small.back(), l = large.back();
    small.pop_back();
    lights[s].alias_q = scaled[s];
    lights[s].alias = std::uint32_t(l);
    scaled[l] -= 1 - scaled[s];
    if (scaled[l] < 1) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left keeps its whole slot (rounding leaves the last ones a hair from 1).
  for (std::size_t k : small) lights[k].alias_q = 1, lights[k].alias = std::uint32_t(k);
  for (std::size_t k : large) lights[k].alias_q = 1, lights[k].alias = std::uint32_t(k);
}

// Rec. 709 luminance.
double luminance(const color& c) {
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// An RGBE texel's radiance, as environment.h's environment_texel decodes it (in double).
color decode(std::uint32_t w) {
  const std::uint32_t e = w >> 24;
  if (e == 0) return color(0);
  const double s = std::ldexp(1.0, int(e) - 136);
  return color((w & 255) * s, ((w >> 8) & 255) * s, ((w >> 16) & 255) * s);
}

// Writes a CDF of the weights (n + 1 entries from `out`): 0, the running sums over their total,
// 1; a uniform one where the total is 0. Returns the total.
double write_cdf(const std::vector<double>& weights, float* out) {
  double total = 0;
  for (double w : weights) total += w;
  const std::size_t n = weights.size();
  double sum = 0;
  out[0] = 0.0f;
  for (std::size_t i = 1; i < n; ++i) {
    sum += weights[i - 1];
    out[i] = total > 0 ? float(sum / total) : float(double(i) / double(n));
  }
  out[n] = 1.0f;
  return total;
}

// ceil(log2(n)): the trips of environment_search over n steps.
std::uint32_t search_trips(std::uint64_t n) {
  std::uint32_t trips = 0;
  while ((std::uint64_t(1) << trips) < n) ++trips;
  return trips;
}

}  // namespace

double lamp_power(const light_record& l) {
  if ((l.flags & RTVK_LIGHT_UNEVEN) != 0u) return 0;
  const double luminance = 0.2126 * l.emission.x + 0.7152 * l.emission.y + 0.0722 * l.emission.z;
  const double area =
      l.kind == RTVK_LIGHT_SPHERE ? 4 * std::numbers::pi * l.radius * l.radius : l.area;
  const double sides =
      l.kind != RTVK_LIGHT_SPHERE && (l.flags & RTVK_LIGHT_ONE_SIDED) == 0u ? 2 : 1;
  const double p = std::max(0.0, luminance) * area * sides;
  return std::isfinite(p) ? p : 0;
}

std::vector<light_record> scene_lights(const scene& s) {
  std::vector<light_record> out;
  for (const sphere& sp : s.spheres)
    if (is_lamp(s, sp.material)) out.push_back(as_lamp(sphere_light(sp), s, sp.material, false));
  for (const quad& q : s.quads)
    if (is_lamp(s, q.material))
      out.push_back(as_lamp(flat_light(RTVK_LIGHT_QUAD, q.Q, q.u, q.v), s, q.material, false));
  for (const triangle& t : s.triangles)
    if (is_lamp(s, t.material))
      out.push_back(
          as_lamp(flat_light(RTVK_LIGHT_TRIANGLE, t.p[0], t.p[1] - t.p[0], t.p[2] - t.p[0]), s,
                  t.material, has_colors(s, t)));
  build_alias_table(out, out.size());  // the lamps, all pushed so far
  for (const sphere& sp : s.spheres)
    if (sp.sampled && !is_lamp(s, sp.material)) out.push_back(sphere_light(sp));
  for (const quad& q : s.quads)
    if (q.sampled && !is_lamp(s, q.material))
      out.push_back(flat_light(RTVK_LIGHT_QUAD, q.Q, q.u, q.v));
  return out;
}

std::vector<light_record> group_lamps(const scene& s) {
  std::vector<light_record> out;
  for (const instance& i : s.instances) {
    const object_group& g = s.groups[i.group];
    const transform& t = i.placement;
    for (const sphere& sp : g.spheres)
      if (is_lamp(s, sp.material))
        if (const std::optional<sphere> w = placed(sp, t))  // none: an ellipsoid
          out.push_back(as_lamp(sphere_light(*w), s, sp.material, false));
    for (const quad& q : g.quads)
      if (is_lamp(s, q.material)) {
        const quad w = placed(q, t);
        out.push_back(as_lamp(flat_light(RTVK_LIGHT_QUAD, w.Q, w.u, w.v), s, q.material, false));
      }
    for (const triangle& tri : g.triangles)
      if (is_lamp(s, tri.material)) {
        const triangle w = placed(tri, t);
        const bool colored = tri.shading >= 0 && g.shading[std::size_t(tri.shading)].has_color;
        out.push_back(
            as_lamp(flat_light(RTVK_LIGHT_TRIANGLE, w.p[0], w.p[1] - w.p[0], w.p[2] - w.p[0]), s,
                    tri.material, colored));
      }
  }
  return out;
}

std::vector<light_record> scene_lamps(const scene& s) {
  std::vector<light_record> out = scene_lights(s);
  std::erase_if(out, [](const light_record& l) { return (l.flags & RTVK_LIGHT_EMITS) == 0u; });
  const std::vector<light_record> placed_lamps = group_lamps(s);
  if (placed_lamps.empty()) return out;
  out.insert(out.end(), placed_lamps.begin(), placed_lamps.end());
  build_alias_table(out, out.size());  // over them all
  return out;
}

void resolve_sampling(scene& s) {
  if (s.render.sampling == sampling_mode::automatic && !s.punctual_lights.empty())
    s.render.sampling = sampling_mode::nee;
}

bool samples_lights(std::size_t lights, sampling_mode m) {
  if (m == sampling_mode::plain || m == sampling_mode::nee) return false;
  if (m == sampling_mode::lights) return true;
  return lights > 0 && lights <= RTVK_MAX_LIGHTS;
}

void check_sampling(const scene& s, const render_settings& rs, const std::string& what) {
  if (rs.sampling == sampling_mode::nee) {
    return;  // any number of lamps: the light tree draws them in its depth of steps
  }
  if (rs.sampling != sampling_mode::lights) return;
  const std::size_t n = scene_lights(s).size();
  if (n == 0)
    throw std::invalid_argument(what +
                                " lights: the scene has no lights to aim at (no diffuse_light "
                                "object, none marked \"sample\")");
  if (n > RTVK_MAX_LIGHTS)
    throw std::invalid_argument(what + " lights: the scene has " + std::to_string(n) +
                                " lights; lights sampling aims at most " +
                                std::to_string(RTVK_MAX_LIGHTS) + " (use plain)");
}

std::uint32_t pixel_strata(const render_settings& rs, bool lights) {
  if (!lights || !rs.jitter) return 1;
  return std::uint32_t(std::sqrt(double(rs.spp)));  // exact for spp <= 2^20
}

const char* sampling_name(sampling_mode m) {
  switch (m) {
    case sampling_mode::plain:
      return "plain";
    case sampling_mode::lights:
      return "lights";
    case sampling_mode::nee:
      return "nee";
    default:
      return "auto";
  }
}

const char* punctual_kind_name(punctual_kind k) {
  switch (k) {
    case punctual_kind::point:
      return "point";
    case punctual_kind::spot:
      return "spot";
    case punctual_kind::directional:
      return "directional";
  }
  return "point";
}

punctual_record punctual_record_of(const punctual_light& l) {
  constexpr double radians = std::numbers::pi / 180;
  punctual_record r;
  r.position = l.position;
  r.direction = glm::normalize(l.direction);
  r.intensity = l.tint * l.intensity;
  switch (l.kind) {
    case punctual_kind::point:
      r.kind = RTVK_PUNCTUAL_POINT;
      break;
    case punctual_kind::spot:
      r.kind = RTVK_PUNCTUAL_SPOT;
      break;
    case punctual_kind::directional:
      r.kind = RTVK_PUNCTUAL_DIRECTIONAL;
      break;
  }
  if (l.kind == punctual_kind::spot) {  // KHR_lights_punctual's reference code
    const double cos_inner = std::cos(l.inner_cone * radians);
    const double cos_outer = std::cos(l.outer_cone * radians);
    r.angle_scale = 1 / std::max(0.001, cos_inner - cos_outer);
    r.angle_offset = -cos_outer * r.angle_scale;
  }
  // 1 - cos(theta_max) as 2 sin^2(theta_max / 2): exact for a small sun.
  const double half_angle = 0.5 * l.angular_diameter * radians;
  if (l.kind == punctual_kind::directional && l.angular_diameter > 0)
    r.cone_gap = 2 * std::sin(0.5 * half_angle) * std::sin(0.5 * half_angle);
  return r;
}

std::vector<punctual_record> punctual_records(const std::vector<punctual_light>& lights) {
  std::vector<punctual_record> out;
  for (const punctual_light& l : lights) out.push_back(punctual_record_of(l));
  return out;
}

std::vector<float> environment_table_of(const environment_map& e) {
  const environment_image& image = *e.image;
  const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
  std::vector<float> table(RTVK_ENV_HEADER + (h + 1) + h * (w + 1), 0.0f);
  const double radians = e.rotation * 3.14159265358979323846 / 180.0;
  table[RTVK_ENV_WIDTH] = float(w);
  table[RTVK_ENV_HEIGHT] = float(h);
  table[RTVK_ENV_STRENGTH] = float(e.strength);
  table[RTVK_ENV_COS] = float(std::cos(radians));
  table[RTVK_ENV_SIN] = float(std::sin(radians));
  table[RTVK_ENV_VISIBLE] = e.visible ? 1.0f : 0.0f;
  table[RTVK_ENV_TRIPS] = float(search_trips(w) + search_trips(h));
  // Each texel weighs its luminance times sin(theta) at its row's center: the solid angle a row
  // spans shrinks toward the poles.
  std::vector<double> rows(h), texels(w);
  for (std::size_t y = 0; y < h; ++y) {
    const double sin_theta = std::sin(3.14159265358979323846 * (double(y) + 0.5) / double(h));
    for (std::size_t x = 0; x < w; ++x)
      texels[x] = luminance(decode(image.texels[y * w + x])) * sin_theta;
    rows[y] = write_cdf(texels, &table[RTVK_ENV_HEADER + h + 1 + y * (w + 1)]);
  }
  write_cdf(rows, &table[RTVK_ENV_HEADER]);
  return table;
}

}  // namespace rtvk
