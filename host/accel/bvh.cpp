#include "bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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
constexpr double traversal_cost = 1.0;  // relative to one sphere test

// Float corners that contain the double box, with a margin for the float slab test on the GPU.
void store_bounds(const box& b, gpu::bvh_node& n) {
  const glm::dvec3 extent = glm::abs(b.lo) + glm::abs(b.hi) + (b.hi - b.lo);
  const double pad = 0x1p-18 * std::max({extent.x, extent.y, extent.z, 1e-30});
  for (int k = 0; k < 3; ++k) {
    n.bounds_min[k] = std::nextafter(float(b.lo[k] - pad), -INFINITY);
    n.bounds_max[k] = std::nextafter(float(b.hi[k] + pad), INFINITY);
  }
}

class builder {
 public:
  builder(std::vector<prim>& prims, std::vector<gpu::bvh_node>& nodes,
          std::vector<std::uint32_t>& index)
      : prims_(prims), nodes_(nodes), index_(index) {}

  // Builds the subtree over prims_[begin, end), `depth` levels below the root.
  void build(std::size_t begin, std::size_t end, int depth) {
    const std::size_t at = nodes_.size();
    nodes_.push_back({});
    box bounds, centroids;
    for (std::size_t i = begin; i < end; ++i) {
      bounds.grow(prims_[i].bounds);
      centroids.grow(prims_[i].centroid);
    }
    store_bounds(bounds, nodes_[at]);
    const std::size_t count = end - begin;
    std::size_t mid = count > std::size_t(bvh::max_leaf) && depth < bvh::max_depth
                          ? split(begin, end, bounds, centroids)
                          : begin;
    if (mid == begin || mid == end) {
      if (count > std::size_t(bvh::max_leaf) && depth < bvh::max_depth) {
        mid = begin + count / 2;  // no useful split (e.g. equal centers): halve by order
      } else {
        make_leaf(at, begin, end);
        return;
      }
    }
    build(begin, mid, depth + 1);
    nodes_[at].first = std::uint32_t(nodes_.size());
    nodes_[at].count = 0;
    build(mid, end, depth + 1);
  }

 private:
  void make_leaf(std::size_t at, std::size_t begin, std::size_t end) {
    nodes_[at].first = std::uint32_t(index_.size());
    nodes_[at].count = std::uint32_t(end - begin);
    for (std::size_t i = begin; i < end; ++i) index_.push_back(prims_[i].sphere);
  }

  // The binned SAH split over all three axes; returns the partition point, or `begin` when
  // keeping a leaf is cheaper (only allowed for small counts, checked by the caller).
  std::size_t split(std::size_t begin, std::size_t end, const box& bounds, const box& centroids) {
    const std::size_t count = end - begin;
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
    const double leaf_cost = double(count);
    const double split_cost = traversal_cost + best_cost / bounds.area();
    if (split_cost >= leaf_cost && count <= std::size_t(bvh::max_leaf)) return begin;
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
  std::vector<std::uint32_t>& index_;
};

}  // namespace

bvh::bvh(std::span<const sphere> spheres) {
  if (spheres.empty()) return;
  std::vector<prim> prims;
  prims.reserve(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const sphere& s = spheres[i];
    const glm::dvec3 r(std::abs(s.radius));
    prims.push_back({box{s.center - r, s.center + r}, s.center, std::uint32_t(i)});
  }
  nodes_.reserve(2 * spheres.size() / std::size_t(max_leaf) + 1);
  index_.reserve(spheres.size());
  builder(prims, nodes_, index_).build(0, prims.size(), 1);
  children_.resize(nodes_.size());
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (nodes_[i].count > 0) continue;
    const gpu::bvh_node& l = nodes_[i + 1];
    const gpu::bvh_node& r = nodes_[nodes_[i].first];
    children_[i] = {{l.bounds_min.x, r.bounds_min.x, l.bounds_max.x, r.bounds_max.x},
                    {l.bounds_min.y, r.bounds_min.y, l.bounds_max.y, r.bounds_max.y},
                    {l.bounds_min.z, r.bounds_min.z, l.bounds_max.z, r.bounds_max.z}};
  }
}

}  // namespace rtvk
