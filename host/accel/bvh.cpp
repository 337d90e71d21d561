#include "bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_invoke.h>
#include <oneapi/tbb/parallel_reduce.h>

#include "bvh_build.h"
#include "parallel.h"

namespace rtvk {
namespace {

using namespace bvh_build;

// Float corners that contain the box, with a margin for the float slab test: lane c (0 left,
// 1 right) of the node's min lanes and lane c + 2 of its max lanes. The margin, 2^-18 of the
// box's largest coordinate and extent, is computed in float: corner - margin rounds to nearest
// and next_down then steps below it, so the stored corner is never inside the exact one.
void store_bounds(const fbox& f, bvh_node& n, int c) {
  const float4 extent = (f.lo < 0 ? -f.lo : f.lo) + (f.hi < 0 ? -f.hi : f.hi) + (f.hi - f.lo);
  const float pad = 0x1p-18f * std::max({extent[0], extent[1], extent[2], 1e-30f});
  glm::vec4* const axes[3] = {&n.x, &n.y, &n.z};
  for (int k = 0; k < 3; ++k) {
    (*axes[k])[c] = next_down(f.lo[k] - pad);
    (*axes[k])[c + 2] = next_up(f.hi[k] + pad);
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

// The bins of one range along one axis: each prim lands, by its centroid, in one bin.
struct bin_set {
  fbox box[bins];                  // the prims' boxes
  std::uint32_t count[bins] = {};  // and their number

  void add(const bin_set& o) {
    for (int b = 0; b < bins; ++b) {
      box[b].grow(o.box[b]);
      count[b] += o.count[b];
    }
  }
};

// Which bin of `axis` a centroid falls in, for centroids spanning [lo, lo + extent).
struct binning {
  float4 lo;     // centroid bounds' low corner
  float4 scale;  // bins / extent per axis (0 where the centroids do not spread)
  explicit binning(const fbox& centroids) : lo(centroids.lo), scale(splat4(0)) {
    const float4 extent = centroids.hi - centroids.lo;
    for (int k = 0; k < 3; ++k) scale[k] = extent[k] > 0 ? float(bins) / extent[k] : 0.0f;
  }
  int bin(float4 c, int axis) const {
    return std::clamp(int((c[axis] - lo[axis]) * scale[axis]), 0, bins - 1);
  }
};

class builder {
 public:
  builder(prim_vector& prims, std::vector<bvh_node>& nodes, std::vector<std::uint32_t>& order)
      : prims_(prims), nodes_(nodes), order_(order) {}

  // Fills interior node `at` over prims_[begin, end) (more than max_leaf spheres), `depth` levels
  // below the root (the root is 1), and its subtrees; returns the deepest level built. Node
  // positions follow from the ranges alone (a subtree over n > 1 spheres has n - 1 interior
  // nodes, stored depth first; leaf slots are prim positions), so subtrees built in parallel land
  // exactly where a sequential build puts them. Takes levels_needed(end - begin) <= max_depth -
  // depth + 1: its children then fit as well.
  int build(std::uint32_t at, std::size_t begin, std::size_t end, const range_info& info,
            int depth) {
    range_info left, right;
    const std::size_t mid = split(begin, end, info, depth, left, right);
    const std::uint32_t left_nodes = mid - begin > 1 ? std::uint32_t(mid - begin - 1) : 0;
    int below[2] = {depth, depth};
    const auto left_child = [&] { below[0] = child(at, 0, begin, mid, left, at + 1, depth); };
    const auto right_child = [&] {
      below[1] = child(at, 1, mid, end, right, at + 1 + left_nodes, depth);
    };
    if (end - begin > parallel_subtree) {
      tbb::parallel_invoke(left_child, right_child);
    } else {
      left_child();
      right_child();
    }
    return std::max(below[0], below[1]);
  }

  // A root for max_leaf spheres or fewer: both children are the same leaf.
  void build_leaf_root(const range_info& info) {
    store_bounds(info.bounds, nodes_[0], 0);
    store_bounds(info.bounds, nodes_[0], 1);
    nodes_[0].first = glm::uvec2(0);
    nodes_[0].count = glm::uvec2(std::uint32_t(prims_.size()));
    for (std::size_t i = 0; i < prims_.size(); ++i) order_[i] = prims_[i].object;
  }

 private:
  // Child c of node `at`: the spheres prims_[begin, end), a leaf or the interior node `node`.
  int child(std::uint32_t at, int c, std::size_t begin, std::size_t end, const range_info& info,
            std::uint32_t node, int depth) {
    store_bounds(info.bounds, nodes_[at], c);
    if (end - begin <= std::size_t(bvh::max_leaf)) {
      nodes_[at].first[c] = std::uint32_t(begin);
      nodes_[at].count[c] = std::uint32_t(end - begin);
      for (std::size_t i = begin; i < end; ++i) order_[i] = prims_[i].object;
      return depth;
    }
    nodes_[at].first[c] = node;
    nodes_[at].count[c] = 0;
    return build(node, begin, end, info, depth + 1);
  }

  // Partitions prims_[begin, end) for node `depth` levels down, returning the partition point
  // and both sides' range_info: binned SAH, or a median split when SAH separates nothing or
  // would need more levels on one side than are left (on skewed input, sizes or places growing
  // geometrically, it would chain thousands of levels; a median split always fits).
  std::size_t split(std::size_t begin, std::size_t end, const range_info& info, int depth,
                    range_info& left, range_info& right) {
    const int levels_left = bvh::max_depth - depth;
    if (end - begin <= small_range) {
      const std::size_t mid = sweep_split(begin, end, info, left, right);
      if (levels_needed(mid - begin) <= levels_left && levels_needed(end - mid) <= levels_left)
        return mid;
      return median(begin, end, info, left, right);
    }
    // Binned along the axis where the centroids spread most: a third of the work of binning
    // all three, for trees that trace within a few percent as fast (docs/benchmarks.md).
    const binning where(info.centroids);
    const int axis = widest_axis(info.centroids);
    int last_left_bin = -1;
    best_sah(bin_prims(begin, end, where, axis), last_left_bin);
    if (last_left_bin >= 0) {
      // The bins' boundary as a coordinate: lo + hi < 2 * boundary is centroid < boundary
      // without the bin arithmetic (a prim on the boundary may go either way, which only moves
      // the split by that prim: the sides' bounds are gathered from the prims themselves).
      const float twice_boundary =
          2.0f * (where.lo[axis] + float(last_left_bin + 1) / where.scale[axis]);
      const std::size_t mid = partition(
          begin, end, [&](const prim& p) { return p.lo[axis] + p.hi[axis] < twice_boundary; }, left,
          right);
      if (mid != begin && mid != end && levels_needed(mid - begin) <= levels_left &&
          levels_needed(end - mid) <= levels_left)
        return mid;
    }
    return median(begin, end, info, left, right);
  }

  // Exact SAH for a few prims (binning them would cost more than the node is worth): sorted
  // along the axis where their centroids spread most, every split point is tried.
  std::size_t sweep_split(std::size_t begin, std::size_t end, const range_info& info,
                          range_info& left, range_info& right) {
    const std::size_t n = end - begin;
    const int axis = widest_axis(info.centroids);
    prim* const p = prims_.data() + begin;
    for (std::size_t i = 1; i < n; ++i)  // insertion sort: n is small
      for (std::size_t j = i; j > 0 && p[j].centroid()[axis] < p[j - 1].centroid()[axis]; --j)
        std::swap(p[j], p[j - 1]);
    double right_area[small_range] = {};
    fbox acc;
    for (std::size_t i = n - 1; i > 0; --i) {
      acc.grow(p[i].lo, p[i].hi);
      right_area[i] = acc.half_area();
    }
    fbox prefix;
    double best_cost = std::numeric_limits<double>::infinity();
    std::size_t best = 1;
    for (std::size_t i = 1; i < n; ++i) {  // left: p[0, i)
      prefix.grow(p[i - 1].lo, p[i - 1].hi);
      const double cost = prefix.half_area() * double(i) + right_area[i] * double(n - i);
      if (cost < best_cost) {
        best_cost = cost;
        best = i;
      }
    }
    left = right = {};
    for (std::size_t i = 0; i < best; ++i) grow(left, p[i]);
    for (std::size_t i = best; i < n; ++i) grow(right, p[i]);
    return begin + best;
  }

  static int widest_axis(const fbox& centroids) {
    const float4 e = centroids.hi - centroids.lo;
    return e[0] >= e[1] && e[0] >= e[2] ? 0 : e[1] >= e[2] ? 1 : 2;
  }

  bin_set bin_prims(std::size_t begin, std::size_t end, const binning& where, int axis) const {
    const auto bin_range = [&](std::size_t from, std::size_t to, bin_set& set) {
      for (std::size_t i = from; i < to; ++i) {
        const prim& p = prims_[i];
        const int b = where.bin(p.centroid(), axis);
        set.box[b].grow(p.lo, p.hi);
        ++set.count[b];
      }
    };
    if (end - begin <= parallel_bins) {
      bin_set set;
      bin_range(begin, end, set);
      return set;
    }
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(begin, end, parallel_bins / 4), bin_set{},
        [&](const tbb::blocked_range<std::size_t>& r, bin_set set) {
          bin_range(r.begin(), r.end(), set);
          return set;
        },
        [](bin_set a, const bin_set& b) {
          a.add(b);
          return a;
        });
  }

  // The cheapest split of the bins by the surface area heuristic; last_left_bin stays -1 when
  // no bin boundary has prims on both sides.
  static void best_sah(const bin_set& set, int& last_left_bin) {
    double best_cost = std::numeric_limits<double>::infinity();
    // Sweep from the right to know each suffix's area and count.
    double right_area[bins] = {};
    std::size_t right_count[bins] = {};
    fbox acc;
    std::size_t n = 0;
    for (int b = bins - 1; b > 0; --b) {
      acc.grow(set.box[b]);
      n += set.count[b];
      right_area[b] = acc.half_area();
      right_count[b] = n;
    }
    fbox left;
    std::size_t left_n = 0;
    for (int b = 0; b < bins - 1; ++b) {
      left.grow(set.box[b]);
      left_n += set.count[b];
      if (left_n == 0 || right_count[b + 1] == 0) continue;
      const double cost =
          left.half_area() * double(left_n) + right_area[b + 1] * double(right_count[b + 1]);
      if (cost < best_cost) {
        best_cost = cost;
        last_left_bin = b;
      }
    }
  }

  // Moves the prims for which goes_left holds to the front; gathers both sides' bounds on the way.
  template <typename Pred>
  std::size_t partition(std::size_t begin, std::size_t end, Pred goes_left, range_info& left,
                        range_info& right) {
    left = right = {};
    std::size_t i = begin, j = end;
    while (true) {
      while (i < j && goes_left(prims_[i])) grow(left, prims_[i++]);
      while (i < j && !goes_left(prims_[j - 1])) grow(right, prims_[--j]);
      if (i >= j) break;
      std::swap(prims_[i], prims_[j - 1]);
    }
    return i;
  }

  static void grow(range_info& info, const prim& p) {
    info.bounds.grow(p.lo, p.hi);
    info.centroids.grow(p.centroid());
  }

  // Halves the spheres by count, at the median centroid along the axis where the centroids
  // spread most (by order when they all coincide).
  std::size_t median(std::size_t begin, std::size_t end, const range_info& info, range_info& left,
                     range_info& right) {
    const int axis = widest_axis(info.centroids);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(prims_.begin() + std::ptrdiff_t(begin), prims_.begin() + std::ptrdiff_t(mid),
                     prims_.begin() + std::ptrdiff_t(end), [axis](const prim& a, const prim& b) {
                       return a.centroid()[axis] < b.centroid()[axis];
                     });
    left = right = {};
    for (std::size_t i = begin; i < mid; ++i) grow(left, prims_[i]);
    for (std::size_t i = mid; i < end; ++i) grow(right, prims_[i]);
    return mid;
  }

  prim_vector& prims_;
  std::vector<bvh_node>& nodes_;
  std::vector<std::uint32_t>& order_;
};

}  // namespace

bvh::bvh(std::span<const sphere> spheres, int threads, time_span motion)
    : bvh(primitive_spans{spheres, {}, {}}, threads, motion) {}

bvh::bvh(const primitive_spans& objects, int threads, time_span motion) {
  const std::size_t count = objects.size();
  if (count == 0) return;
  if (levels_needed(count) > max_depth || count > std::size_t(RTVK_LEAF_INDEX_MASK) + 1)
    throw std::length_error(std::to_string(count) + " objects are more than a BVH of " +
                            std::to_string(max_depth) + " levels holds");
  run_in_arena(threads, [&] {
    prim_vector prims;
    const range_info all = make_prims(objects, motion, prims);
    // A binary tree over N >= 2 one-object leaves has N - 1 interior nodes; one object, a root.
    nodes_.resize(std::max<std::size_t>(count - 1, 1));
    order_.resize(count);
    builder b(prims, nodes_, order_);
    if (count <= std::size_t(max_leaf)) {
      b.build_leaf_root(all);
      depth_ = 1;
    } else {
      depth_ = b.build(0, 0, prims.size(), all, 1);
    }
  });
}

}  // namespace rtvk
