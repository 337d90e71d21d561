#include "light_sources.h"

#include <cmath>
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
