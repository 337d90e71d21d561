#include "obj_polygon.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace rtvk {
namespace {

using point2 = glm::dvec2;

double cross(const point2& a, const point2& b) {
  return a.x * b.y - a.y * b.x;
}

// Counter-clockwise turn at b (a -> b -> c) in the face's plane: > 0 convex, 0 straight.
double turn(const point2& a, const point2& b, const point2& c) {
  return cross(b - a, c - b);
}

// Whether p lies inside triangle abc (counter-clockwise) or on its edges.
bool inside_or_on(const point2& p, const point2& a, const point2& b, const point2& c) {
  return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

// The corners in the face's plane, counter-clockwise seen from Newell's normal; false for a
// face without area (a zero normal).
bool flatten(const std::vector<vec3>& p, std::vector<point2>& out) {
  vec3 n(0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const vec3& a = p[i];
    const vec3& b = p[(i + 1) % p.size()];
    n += vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const double length = glm::length(n);
  if (!(length > 0) || !std::isfinite(length)) return false;
  n /= length;
  // Any u across n, and v = n x u: (u, v, n) right-handed, so counter-clockwise about n stays so.
  const vec3 u = glm::normalize(std::abs(n.x) > 0.9 ? glm::cross(n, vec3(0, 1, 0))
                                                    : glm::cross(n, vec3(1, 0, 0)));
  const vec3 v = glm::cross(n, u);
  out.clear();
  for (const vec3& q : p) out.emplace_back(glm::dot(q, u), glm::dot(q, v));
  return true;
}

// Whether the corner `at` of the ring (indices into q) is an ear: convex, and no other corner
// of the ring inside or on the triangle it cuts off (corners at the same place as the
// triangle's own, as where a ring is cut open, do not count).
bool is_ear(const std::vector<point2>& q, const std::vector<std::size_t>& ring, std::size_t at) {
  const std::size_t n = ring.size();
  const point2& a = q[ring[(at + n - 1) % n]];
  const point2& b = q[ring[at]];
  const point2& c = q[ring[(at + 1) % n]];
  if (!(turn(a, b, c) > 0)) return false;
  for (std::size_t k = 0; k < n; ++k) {
    const point2& p = q[ring[k]];
    if (p == a || p == b || p == c) continue;
    if (inside_or_on(p, a, b, c)) return false;
  }
  return true;
}

std::vector<std::array<std::size_t, 3>> fan(std::size_t n) {
  std::vector<std::array<std::size_t, 3>> out;
  for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
  return out;
}

// tinyobjloader's cut of a quad: along the shorter diagonal.
std::vector<std::array<std::size_t, 3>> quad(const std::vector<vec3>& p) {
  const vec3 e02 = p[2] - p[0], e13 = p[3] - p[1];
  if (glm::dot(e02, e02) < glm::dot(e13, e13)) return {{0, 1, 2}, {0, 2, 3}};
  return {{0, 1, 3}, {1, 2, 3}};
}

}  // namespace

std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<vec3>& corners) {
  const std::size_t n = corners.size();
  if (n < 3) return {};
  if (n == 3) return {{0, 1, 2}};
  std::vector<point2> q;
  if (n > max_ear_clipped_corners || !flatten(corners, q)) return fan(n);
  bool convex = true;
  for (std::size_t i = 0; i < n; ++i)
    convex = convex && turn(q[(i + n - 1) % n], q[i], q[(i + 1) % n]) >= 0;
  if (n == 4 && convex) return quad(corners);

  std::vector<std::size_t> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = i;
  std::vector<std::array<std::size_t, 3>> out;
  std::size_t at = 0, tried = 0;  // the corner to try next; corners tried since the last cut
  while (ring.size() > 3) {
    const std::size_t m = ring.size();
    const point2& a = q[ring[(at + m - 1) % m]];
    const point2& c = q[ring[(at + 1) % m]];
    // A straight corner is cut off as a triangle without area: it leaves the outline unchanged.
    // Where no ear is left (a face crossing itself), the corner is cut anyway.
    const bool straight = turn(a, q[ring[at]], c) == 0;
    if (straight || is_ear(q, ring, at) || tried >= m) {
      out.push_back({ring[(at + m - 1) % m], ring[at], ring[(at + 1) % m]});
      ring.erase(ring.begin() + std::ptrdiff_t(at));
      if (at >= ring.size()) at = 0;
      tried = 0;
    } else {
      at = (at + 1) % m;
      ++tried;
    }
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

}  // namespace rtvk
