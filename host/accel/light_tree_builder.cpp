#include "light_tree_builder.h"
#include "light_sources.h"
#include "light_tree.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace rtvk {
namespace {

constexpr double half_turn = std::numbers::pi;  // pi radians (the kernels have a `pi` of their own)

// A cone of directions: unit axis w and the cosine of its half angle (-1: every direction).
struct cone {
  vec3 w{0, 0, 1};
  double cos_theta = -1;
};

// What a node bounds, in double while the tree is built: the box, the cone of the normals, how
// far past them light leaves (cos theta_e), the power, and the lamps' centroid for the split.
struct bounds {
  vec3 lo{std::numeric_limits<double>::infinity()};
  vec3 hi{-std::numeric_limits<double>::infinity()};
  cone normals;
  double cos_e = 1;
  double power = 0;
  vec3 centroid{0};
  std::uint32_t lamp = 0;
};

// v turned by `angle` radians about the unit axis k (Rodrigues' formula).
vec3 rotated(const vec3& v, const vec3& k, double angle) {
  return v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) +
         k * glm::dot(k, v) * (1 - std::cos(angle));
}

// The smallest cone holding both (pbrt-v4's DirectionCone::Union).
cone cone_union(const cone& a, const cone& b) {
  if (a.cos_theta <= -1 || b.cos_theta <= -1) return {};
  const double theta_a = std::acos(std::clamp(a.cos_theta, -1.0, 1.0));
  const double theta_b = std::acos(std::clamp(b.cos_theta, -1.0, 1.0));
  const double theta_d = std::acos(std::clamp(glm::dot(a.w, b.w), -1.0, 1.0));
  if (std::min(theta_d + theta_b, half_turn) <= theta_a) return a;
  if (std::min(theta_d + theta_a, half_turn) <= theta_b) return b;
  const double theta_o = (theta_a + theta_d + theta_b) / 2;
  const vec3 k = glm::cross(a.w, b.w);
  if (theta_o >= half_turn || !(glm::length(k) > 1e-12)) return {};
  return {glm::normalize(rotated(a.w, glm::normalize(k), theta_o - theta_a)), std::cos(theta_o)};
}

bounds merged(const bounds& a, const bounds& b) {
  if (!(a.power > 0)) return b;
  if (!(b.power > 0)) return a;
  bounds m;
  m.lo = glm::min(a.lo, b.lo);
  m.hi = glm::max(a.hi, b.hi);
  m.normals = cone_union(a.normals, b.normals);
  m.cos_e = std::min(a.cos_e, b.cos_e);
  m.power = a.power + b.power;
  return m;
}

// Lamp l's bounds: a sphere over its motion (light in every direction), a quad or a
// triangle by its corners (one-sided: its normal's half space; two-sided: every direction).
bounds lamp_bounds(const light_record& l, std::uint32_t index, time_span motion) {
  bounds b;
  b.power = lamp_power(l);
  b.lamp = index;
  b.cos_e = 0;  // a lamp's light leaves up to 90 degrees from its normal
  if (l.kind == RTVK_LIGHT_SPHERE) {
    const vec3 r(l.radius);
    const point3 first = l.a + motion.lo * l.u, last = l.a + motion.hi * l.u;
    b.lo = glm::min(first, last) - r;
    b.hi = glm::max(first, last) + r;
  } else {
    for (const vec3& c : {l.a, l.a + l.u, l.a + l.v, l.a + l.u + l.v}) {
      if (l.kind == RTVK_LIGHT_TRIANGLE && c == l.a + l.u + l.v) continue;
      b.lo = glm::min(b.lo, c);
      b.hi = glm::max(b.hi, c);
    }
    if ((l.flags & RTVK_LIGHT_ONE_SIDED) != 0u) b.normals = {l.normal, 1};
  }
  b.centroid = (b.lo + b.hi) * 0.5;
  return b;
}

double surface_area(const bounds& b) {
  const vec3 d = b.hi - b.lo;
  return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// The solid-angle measure of the cone of normals widened by theta_e (pbrt-v4's M_Omega).
double orientation_measure(const bounds& b) {
  const double theta_o = std::acos(std::clamp(b.normals.cos_theta, -1.0, 1.0));
  const double theta_e = std::acos(std::clamp(b.cos_e, -1.0, 1.0));
  const double theta_w = std::min(theta_o + theta_e, half_turn);
  const double sin_o = std::sin(theta_o);
  return 2 * half_turn * (1 - std::cos(theta_o)) +
         half_turn / 2 *
             (2 * theta_w * sin_o - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * sin_o +
              std::cos(theta_o));
}

// The cost of a node by the surface area orientation heuristic, times the axis's regularizer.
double cost(const bounds& b) {
  return b.power > 0 ? b.power * orientation_measure(b) * surface_area(b) : 0;
}

using item_iter = std::vector<bounds>::iterator;

// Where to split [first, last): the iterator of the first item of the second half. By the
// heuristic over 12 buckets an axis where `heuristic`, else (or where it finds nothing) the
// centroids' median on their widest axis.
item_iter split(item_iter first, item_iter last, const bounds& all, bool heuristic) {
  vec3 clo(std::numeric_limits<double>::infinity()), chi(-clo);
  for (item_iter i = first; i != last; ++i)
    clo = glm::min(clo, i->centroid), chi = glm::max(chi, i->centroid);
  const vec3 extent = chi - clo;
  const double widest = std::max({extent.x, extent.y, extent.z});
  constexpr int buckets = 12;
  double best = std::numeric_limits<double>::infinity();
  int best_axis = -1, best_cut = 0;
  for (int axis = 0; heuristic && axis < 3; ++axis) {
    if (!(extent[axis] > 0)) continue;
    bounds bucket[buckets];
    const auto slot = [&](const bounds& b) {
      return std::min(buckets - 1, int(buckets * (b.centroid[axis] - clo[axis]) / extent[axis]));
    };
    for (item_iter i = first; i != last; ++i) bucket[slot(*i)] = merged(bucket[slot(*i)], *i);
    // The buckets above each cut, merged from the top down once; those below as the cut rises.
    bounds above[buckets];
    for (int k = buckets - 1; k > 0; --k)
      above[k] = k + 1 < buckets ? merged(bucket[k], above[k + 1]) : bucket[k];
    bounds below;
    for (int cut = 1; cut < buckets; ++cut) {
      below = merged(below, bucket[cut - 1]);
      const double c = widest / extent[axis] * (cost(below) + cost(above[cut]));
      if (below.power > 0 && above[cut].power > 0 && c < best)
        best = c, best_axis = axis, best_cut = cut;
    }
  }
  if (best_axis >= 0 && best < std::numeric_limits<double>::infinity() && cost(all) > 0) {
    const int axis = best_axis;
    const item_iter mid = std::partition(first, last, [&](const bounds& b) {
      return std::min(buckets - 1, int(buckets * (b.centroid[axis] - clo[axis]) / extent[axis])) <
             best_cut;
    });
    if (mid != first && mid != last) return mid;
  }
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const item_iter mid = first + (last - first) / 2;
  std::nth_element(first, mid, last, [axis](const bounds& a, const bounds& b) {
    return a.centroid[axis] < b.centroid[axis];
  });
  return mid;
}

std::uint32_t levels(std::size_t n) {  // ceil(log2(n))
  std::uint32_t l = 0;
  while ((std::size_t(1) << l) < n) ++l;
  return l;
}

gpu::gpu_light_node node_of(const bounds& b) {
  gpu::gpu_light_node n{};
  n.lo = gpu::vec3(b.lo);
  n.hi = gpu::vec3(b.hi);
  n.power = float(b.power);
  n.axis = gpu::vec3(b.normals.w);
  n.cos_o = float(b.normals.cos_theta);
  n.cos_e = float(b.cos_e);
  return n;
}

// Appends the subtree over [first, last) at `depth` below the root, reached by `trail`; returns
// its bounds.
bounds build(item_iter first, item_iter last, std::uint32_t depth, std::uint32_t trail,
             std::vector<gpu::gpu_light_node>& nodes) {
  const std::size_t at = nodes.size();
  nodes.emplace_back();
  if (last - first == 1) {
    nodes[at] = node_of(*first);
    nodes[at].leaf = 1;
    nodes[at].lamp = first->lamp;
    nodes[at].second = trail;
    return *first;
  }
  bounds all;
  for (item_iter i = first; i != last; ++i) all = merged(all, *i);
  // The heuristic only while the median could still finish within the depth bound after it.
  const bool heuristic = depth + levels(std::size_t(last - first)) + 4 < light_tree_depth;
  const item_iter mid = split(first, last, all, heuristic);
  const bounds a = build(first, mid, depth + 1, trail, nodes);
  const auto second = std::uint32_t(nodes.size());
  const bounds b = build(mid, last, depth + 1, trail | (1u << depth), nodes);
  const bounds m = merged(a, b);
  nodes[at] = node_of(m);
  nodes[at].second = second;
  return m;
}

}  // namespace

std::vector<gpu::gpu_light_node> build_light_tree(const std::vector<light_record>& lights,
                                                  time_span motion) {
  std::vector<bounds> items;
  for (std::size_t k = 0; k < lights.size(); ++k) {
    if ((lights[k].flags & RTVK_LIGHT_EMITS) == 0u) continue;
    const bounds b = lamp_bounds(lights[k], std::uint32_t(k), motion);
    if (b.power > 0 && std::isfinite(b.power)) items.push_back(b);
  }
  std::vector<gpu::gpu_light_node> nodes;
  if (items.empty()) return {gpu::gpu_light_node{}};  // power 0: nothing to draw
  nodes.reserve(2 * items.size());
  build(items.begin(), items.end(), 0, 0, nodes);
  return nodes;
}

}  // namespace rtvk
