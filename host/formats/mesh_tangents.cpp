#include "mesh_tangents.h"

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace rtvk {
namespace {

// What identifies a vertex for the accumulation: its position, normal and uv, bit for bit, and
// the handedness of the faces around it (true: mirrored uv), as MikkTSpace splits them.
struct vertex_key {
  std::array<double, 8> v{};  // position xyz, normal xyz, uv
  bool mirrored = false;      // the faces' uv run clockwise where their vertices run counter-
  auto operator<=>(const vertex_key&) const = default;
};

// A face's derivatives of position along its texture coordinates, scene units per uv unit.
struct face_derivatives {
  vec3 dpdu{0}, dpdv{0};
  bool mirrored = false;  // its uv area is negative
  bool valid = false;     // its uv span an area (else no tangent can come from it)
};

face_derivatives derivatives_of(const std::array<point3, 3>& p,
                                const std::array<glm::dvec2, 3>& uv) {
  const vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const glm::dvec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
  const double r = d1.x * d2.y - d2.x * d1.y;  // twice the signed uv area
  face_derivatives f;
  if (!(std::abs(r) > 0) || !std::isfinite(r)) return f;
  f.dpdu = (e1 * d2.y - e2 * d1.y) / r;
  f.dpdv = (e2 * d1.x - e1 * d2.x) / r;
  f.mirrored = r < 0;
  f.valid = std::isfinite(glm::dot(f.dpdu, f.dpdu)) && std::isfinite(glm::dot(f.dpdv, f.dpdv));
  return f;
}

// The face's angle at corner k, radians: its weight in the vertex's sum (MikkTSpace's).
double corner_angle(const std::array<point3, 3>& p, std::size_t k) {
  const vec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
  const double la = glm::length(a), lb = glm::length(b);
  if (!(la > 0 && lb > 0)) return 0;
  return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

// v without its part along the unit n, unit; zero where nothing is left.
vec3 across(const vec3& v, const vec3& n) {
  const vec3 t = v - glm::dot(n, v) * n;
  const double len = glm::length(t);
  return len > 0 && std::isfinite(len) ? t / len : vec3(0);
}

// Some unit vector perpendicular to the unit n: the tangent of a vertex no face's uv reach.
vec3 some_perpendicular(const vec3& n) {
  const vec3 axis = std::abs(n.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 1, 0);
  return glm::normalize(glm::cross(axis, n)) * (std::abs(n.x) < 0.9 ? -1.0 : 1.0);
}

struct tangent_sum {
  vec3 t{0}, b{0};  // the faces' projected dp/du and dp/dv, each weighted by its angle
};

}  // namespace

bool normal_mapped_material(const material& m) {
  return m.type == material_type::pbr &&
         (m.pbr.normal_texture >= 0 || m.pbr.clearcoat_normal_texture >= 0);
}

void generate_tangents(scene& s, std::size_t first) {
  // The triangles that get tangents, and each corner's key.
  std::vector<std::size_t> chosen;
  for (std::size_t i = first; i < s.triangles.size(); ++i) {
    const triangle& t = s.triangles[i];
    if (t.shading < 0 || std::size_t(t.material) >= s.materials.size()) continue;
    const triangle_shading& sh = s.shading[std::size_t(t.shading)];
    if (sh.has_normals() && sh.has_uv && !sh.has_tangent &&
        normal_mapped_material(s.materials[std::size_t(t.material)].m))
      chosen.push_back(i);
  }
  if (chosen.empty()) return;
  const auto key_of = [&](const triangle& t, const face_derivatives& f, std::size_t k) {
    const triangle_shading& sh = s.shading[std::size_t(t.shading)];
    vertex_key key;
    key.v = {t.p[k].x,       t.p[k].y,       t.p[k].z,   sh.normal[k].x,
             sh.normal[k].y, sh.normal[k].z, sh.uv[k].x, sh.uv[k].y};
    key.mirrored = f.mirrored;
    return key;
  };
  std::map<vertex_key, tangent_sum> sums;
  for (const std::size_t i : chosen) {
    const triangle& t = s.triangles[i];
    const face_derivatives f = derivatives_of(t.p, s.shading[std::size_t(t.shading)].uv);
    if (!f.valid) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const vec3 n = glm::normalize(s.shading[std::size_t(t.shading)].normal[k]);
      const double angle = corner_angle(t.p, k);
      tangent_sum& sum = sums[key_of(t, f, k)];
      sum.t += angle * across(f.dpdu, n);
      sum.b += angle * across(f.dpdv, n);
    }
  }
  for (const std::size_t i : chosen) {
    const triangle& t = s.triangles[i];
    triangle_shading& sh = s.shading[std::size_t(t.shading)];
    const face_derivatives f = derivatives_of(t.p, sh.uv);
    for (std::size_t k = 0; k < 3; ++k) {
      const vec3 n = glm::normalize(sh.normal[k]);
      tangent_sum sum;
      if (f.valid) sum = sums[key_of(t, f, k)];
      vec3 tangent = across(sum.t, n);
      if (tangent == vec3(0)) tangent = some_perpendicular(n);
      const double w = glm::dot(glm::cross(n, tangent), sum.b) < 0 ? -1 : 1;
      sh.tangent[k] = glm::vec4(glm::vec3(tangent), float(w));
    }
    sh.has_tangent = true;
  }
}

}  // namespace rtvk
