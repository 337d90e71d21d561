#include "bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rtvk {
namespace {

struct box {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  void grow(const box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  void grow(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  double area() const {
    const glm::dvec3 e = hi - lo;
    return e.x < 0 ? 0 : 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

struct prim {
  box bounds;            // the sphere's box
  glm::dvec3 centroid;   // its center
  std::uint32_t sphere;  // index into the scene's spheres
};

constexpr int bins = 16;

// Float corners that contain the double box, with a margin for the float slab test: lane c
// (0 left, 1 right) of the node's min lanes and lane c + 2 of its max lanes.
void store_bounds(const box& b, gpu::bvh_node& n, int c) {
  const glm::dvec3 extent = glm::abs(b.lo) + glm::abs(b.hi) + (b.hi - b.lo);
  const double pad = 0x1p-18 * std::max({extent.x, extent.y, extent.z, 1e-30});
  glm::vec4* const axes[3] = {&n.x, &n.y, &n.z};
  for (int k = 0; k < 3; ++k) {
    (*axes[k])[c] = std::nextafter(float(b.lo[k] - pad), -INFINITY);
    (*axes[k])[c + 2] = std::nextafter(float(b.hi[k] + pad), INFINITY);
  }
}

// Interior levels a subtree over `count` spheres needs at least: ceil(log2(leaves)) for
// ceil(count / max_leaf) leaves; 0 for a leaf.
int levels_needed(std::size_t count) {
  const std::size_t leaves = (count + std::size_t(bvh::max_leaf) - 1) / std::size_t(bvh::max_leaf);
  int levels = 0;
  while (leaves > 1 && (std::size_t(1) << levels) < leaves) ++levels;
  return levels;
}

class builder {
 public:
  builder(std::vector<prim>& prims, std::vector<gpu::bvh_node>& nodes,
          std::vector<std::uint32_t>& order)
      : prims_(prims), nodes_(nodes), order_(order) {}

  // Builds the interior node over prims_[begin, end) (more than max_leaf spheres), `depth`
  // levels below the root (the root is 1), and below it its subtrees; returns its index. Takes
  // levels_needed(end - begin) <= max_depth - depth + 1: its children then fit as well.
  std::uint32_t build(std::size_t begin, std::size_t end, int depth) {
    const std::uint32_t at = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    depth_ = std::max(depth_, depth);
    box centroids;
    for (std::size_t i = begin; i < end; ++i) centroids.grow(prims_[i].centroid);
    std::size_t mid = split(begin, end, centroids);
    // The depth bound: both sides must fit in the levels left below this node. A median split
    // always does (each half needs one level less than the whole); SAH on skewed input (sizes
    // or places growing geometrically) may not, and would chain thousands of levels.
    const int left = bvh::max_depth - depth;
    if (mid == begin || mid == end || levels_needed(mid - begin) > left ||
        levels_needed(end - mid) > left)
      mid = median(begin, end, centroids);
    child(at, 0, begin, mid, depth);
    child(at, 1, mid, end, depth);
    return at;
  }

  // A root for max_leaf spheres or fewer: both children are the same leaf.
  void build_leaf_root(std::size_t begin, std::size_t end) {
    nodes_.push_back({});
    depth_ = 1;
    const box b = bounds(begin, end);
    store_bounds(b, nodes_[0], 0);
    store_bounds(b, nodes_[0], 1);
    nodes_[0].first = gpu::uvec2(std::uint32_t(order_.size()));
    nodes_[0].count = gpu::uvec2(std::uint32_t(end - begin));
    for (std::size_t i = begin; i < end; ++i) order_.push_back(prims_[i].sphere);
  }

  int depth() const { return depth_; }

 private:
  box bounds(std::size_t begin, std::size_t end) const {
    box b;
    for (std::size_t i = begin; i < end; ++i) b.grow(prims_[i].bounds);
    return b;
  }

  // Child c of node `at`: the spheres prims_[begin, end), a leaf or an interior node.
  void child(std::uint32_t at, int c, std::size_t begin, std::size_t end, int depth) {
    store_bounds(bounds(begin, end), nodes_[at], c);
    const std::size_t count = end - begin;
    if (count <= std::size_t(bvh::max_leaf)) {
      nodes_[at].first[c] = std::uint32_t(order_.size());
      nodes_[at].count[c] = std::uint32_t(count);
      for (std::size_t i = begin; i < end; ++i) order_.push_back(prims_[i].sphere);
      return;
    }
    const std::uint32_t node = build(begin, end, depth + 1);
    nodes_[at].first[c] = node;
    nodes_[at].count[c] = 0;
  }

  // Halves the spheres by count, at the median centroid along the axis where the centroids
  // spread most (by order when they all coincide).
  std::size_t median(std::size_t begin, std::size_t end, const box& centroids) {
    const glm::dvec3 extent = centroids.hi - centroids.lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(prims_.begin() + std::ptrdiff_t(begin), prims_.begin() + std::ptrdiff_t(mid),
                     prims_.begin() + std::ptrdiff_t(end), [axis](const prim& a, const prim& b) {
                       return a.centroid[axis] < b.centroid[axis];
                     });
    return mid;
  }

  // The binned SAH split over all three axes; returns the partition point, or `begin` when no
  // bin boundary separates the centroids.
  std::size_t split(std::size_t begin, std::size_t end, const box& centroids) {
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = centroids.lo[axis], extent = centroids.hi[axis] - lo;
      if (!(extent > 0)) continue;
      std::array<box, bins> bin_box;
      std::array<std::size_t, bins> bin_count{};
      for (std::size_t i = begin; i < end; ++i) {
        const int b = bin_of(prims_[i].centroid[axis], lo, extent);
        bin_box[std::size_t(b)].grow(prims_[i].bounds);
        ++bin_count[std::size_t(b)];
      }
      // Sweep from the right to know each suffix's area and count.
      std::array<double, bins> right_area{};
      std::array<std::size_t, bins> right_count{};
      box acc;
      std::size_t n = 0;
      for (int b = bins - 1; b > 0; --b) {
        acc.grow(bin_box[std::size_t(b)]);
        n += bin_count[std::size_t(b)];
        right_area[std::size_t(b)] = acc.area();
        right_count[std::size_t(b)] = n;
      }
      box left;
      std::size_t left_n = 0;
      for (int b = 0; b < bins - 1; ++b) {
        left.grow(bin_box[std::size_t(b)]);
        left_n += bin_count[std::size_t(b)];
        const std::size_t r = std::size_t(b) + 1;
        if (left_n == 0 || right_count[r] == 0) continue;
        const double cost = left.area() * double(left_n) + right_area[r] * double(right_count[r]);
        if (cost < best_cost) {
          best_cost = cost;
          best_axis = axis;
          best_bin = b;
        }
      }
    }
    if (best_axis < 0) return begin;
    const double lo = centroids.lo[best_axis], extent = centroids.hi[best_axis] - lo;
    const auto middle = std::partition(
        prims_.begin() + std::ptrdiff_t(begin), prims_.begin() + std::ptrdiff_t(end),
        [&](const prim& p) { return bin_of(p.centroid[best_axis], lo, extent) <= best_bin; });
    return std::size_t(middle - prims_.begin());
  }

  static int bin_of(double c, double lo, double extent) {
    return std::min(bins - 1, int(double(bins) * (c - lo) / extent));
  }

  std::vector<prim>& prims_;
  std::vector<gpu::bvh_node>& nodes_;
  std::vector<std::uint32_t>& order_;
  int depth_ = 0;  // deepest interior level built
};

}  // namespace

bvh::bvh(std::span<const sphere> spheres) {
  if (spheres.empty()) return;
  if (levels_needed(spheres.size()) > max_depth)
    throw std::length_error(std::to_string(spheres.size()) + " spheres are more than a BVH of " +
                            std::to_string(max_depth) + " levels holds");
  std::vector<prim> prims;
  prims.reserve(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const sphere& s = spheres[i];
    const glm::dvec3 r(std::abs(s.radius));
    prims.push_back({box{s.center - r, s.center + r}, s.center, std::uint32_t(i)});
  }
  nodes_.reserve(spheres.size());  // a binary tree over N >= 2 leaves has N - 1 interior nodes
  order_.reserve(spheres.size());
  builder b(prims, nodes_, order_);
  if (spheres.size() <= std::size_t(max_leaf))
    b.build_leaf_root(0, prims.size());
  else
    b.build(0, prims.size(), 1);
  depth_ = b.depth();
}

}  // namespace rtvk
