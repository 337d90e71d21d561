#include "light_sources.h"
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

}  // namespace

std::vector<light_record> scene_lights(const scene& s) {
  std::vector<light_record> out;
  for (const sphere& sp : s.spheres)
    if (is_lamp(s, sp.material)) out.push_back(sphere_light(sp));
  for (const quad& q : s.quads)
    if (is_lamp(s, q.material)) out.push_back(flat_light(RTVK_LIGHT_QUAD, q.Q, q.u, q.v));
  for (const triangle& t : s.triangles)
    if (is_lamp(s, t.material))
      out.push_back(flat_light(RTVK_LIGHT_TRIANGLE, t.p[0], t.p[1] - t.p[0], t.p[2] - t.p[0]));
  for (const sphere& sp : s.spheres)
    if (sp.sampled && !is_lamp(s, sp.material)) out.push_back(sphere_light(sp));
  for (const quad& q : s.quads)
    if (q.sampled && !is_lamp(s, q.material))
      out.push_back(flat_light(RTVK_LIGHT_QUAD, q.Q, q.u, q.v));
  return out;
}

bool samples_lights(std::size_t lights, sampling_mode m) {
  if (m == sampling_mode::plain) return false;
  if (m == sampling_mode::lights) return true;
  return lights > 0 && lights <= RTVK_MAX_LIGHTS;
}

void check_sampling(const scene& s, const render_settings& rs, const std::string& what) {
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

}  // namespace rtvk
