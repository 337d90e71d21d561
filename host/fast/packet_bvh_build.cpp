// packet_bvh's tree: a binary tree split by the surface area heuristic (binned, leaves of up to
// four objects of one kind), collapsed four wide, each leaf's objects packed lane by lane.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "packet_bvh.h"

namespace rtvk::fast {
namespace {

constexpr float inf = std::numeric_limits<float>::infinity();
constexpr std::uint32_t lanes = 4;  // objects per packet
constexpr int bins = 16;

struct box {
  float lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  void grow(const float* l, const float* h) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], l[k]), hi[k] = std::max(hi[k], h[k]);
  }
  void grow(const box& b) { grow(b.lo, b.hi); }
  void grow(real3 p) {
    const float q[3] = {p.x, p.y, p.z};
    grow(q, q);
  }
  // In double: the costs of boxes 1e16 wide overflow float.
  double half_area() const {
    const double x = double(hi[0]) - double(lo[0]), y = double(hi[1]) - double(lo[1]),
                 z = double(hi[2]) - double(lo[2]);
    return x < 0 ? 0 : x * y + y * z + z * x;
  }
};

// One object as the builder sees it.
struct item {
  box b;
  float c[3];  // the box's center
  std::uint32_t kind, index;
};

// A binary node: a leaf holds items [begin, end), all of one kind, at most `lanes`.
struct binary_node {
  box b;
  int left = -1, right = -1;  // -1: a leaf
  std::uint32_t begin = 0, end = 0;
};

// A box grown by a little more than float's rounding of its corners (fast_world.cpp's grow), so
// that no hit the kernels' float tests find falls outside it.
box grown(box b) {
  float m = 1.0f;
  for (int k = 0; k < 3; ++k) m = std::max({m, std::abs(b.lo[k]), std::abs(b.hi[k])});
  for (int k = 0; k < 3; ++k) b.lo[k] -= 1e-5f * m, b.hi[k] += 1e-5f * m;
  return b;
}

struct builder {
  std::vector<item> items;
  std::vector<binary_node> nodes;

  bool one_kind(std::uint32_t begin, std::uint32_t end) const {
    for (std::uint32_t k = begin + 1; k < end; ++k)
      if (items[k].kind != items[begin].kind) return false;
    return true;
  }

  // Where to split [begin, end): the binned SAH's best plane, or the middle when the centers
  // cannot be told apart. The items are reordered so that the split falls at the returned index.
  std::uint32_t split(std::uint32_t begin, std::uint32_t end, bool median) {
    const std::uint32_t n = end - begin;
    if (n <= lanes) {  // several kinds: the first kind against the rest
      const std::uint32_t first = items[begin].kind;
      return std::uint32_t(
          std::stable_partition(items.begin() + begin, items.begin() + end,
                                [first](const item& i) { return i.kind == first; }) -
          items.begin());
    }
    box centers;
    for (std::uint32_t k = begin; k < end; ++k) centers.grow(items[k].c, items[k].c);
    if (median) {  // the middle of the centers along their longest extent
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (centers.hi[k] - centers.lo[k] > centers.hi[axis] - centers.lo[axis]) axis = k;
      std::nth_element(items.begin() + begin, items.begin() + begin + n / 2, items.begin() + end,
                       [axis](const item& a, const item& b) { return a.c[axis] < b.c[axis]; });
      return begin + n / 2;
    }
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float lo = centers.lo[axis], extent = centers.hi[axis] - lo;
      if (!(extent > 0)) continue;
      box b[bins];
      std::uint32_t count[bins] = {};
      for (std::uint32_t k = begin; k < end; ++k) {
        const int i = std::min(bins - 1, int(float(bins) * (items[k].c[axis] - lo) / extent));
        b[i].grow(items[k].b);
        ++count[i];
      }
      // Costs of every plane: the boxes and packets to the left, swept, then to the right.
      double left_area[bins];
      std::uint32_t left_count[bins];
      box acc;
      std::uint32_t c = 0;
      for (int i = 0; i < bins - 1; ++i) {
        acc.grow(b[i]), c += count[i];
        left_area[i] = acc.half_area(), left_count[i] = c;
      }
      acc = box{}, c = 0;
      for (int i = bins - 1; i > 0; --i) {
        acc.grow(b[i]), c += count[i];
        const std::uint32_t l = left_count[i - 1];
        if (l == 0 || c == 0) continue;
        const double cost = left_area[i - 1] * double((l + lanes - 1) / lanes) +
                            acc.half_area() * double((c + lanes - 1) / lanes);
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = i;
      }
    }
    if (best_axis < 0) return begin + n / 2;
    const float lo = centers.lo[best_axis], extent = centers.hi[best_axis] - lo;
    return std::uint32_t(std::partition(items.begin() + begin, items.begin() + end,
                                        [&](const item& i) {
                                          return std::min(bins - 1,
                                                          int(float(bins) * (i.c[best_axis] - lo) /
                                                              extent)) < best_bin;
                                        }) -
                         items.begin());
  }

  // Binary levels a split of n items may use below its node: each wide level takes at least one,
  // so the wide tree stays within packet_bvh::max_levels. Two are left for splitting a packet's
  // worth of mixed kinds.
  static constexpr int max_depth = packet_bvh::max_levels - 3;

  // Levels median splits need to bring n items down to a packet's worth.
  static int levels_needed(std::uint32_t n) {
    int levels = 0;
    for (; n > lanes; n = (n + 1) / 2) ++levels;
    return levels;
  }

  int build(std::uint32_t begin, std::uint32_t end, int depth) {
    const int at = int(nodes.size());
    nodes.push_back({});
    box b;
    for (std::uint32_t k = begin; k < end; ++k) b.grow(items[k].b);
    nodes[std::size_t(at)].b = b;
    if (end - begin <= lanes && one_kind(begin, end)) {
      nodes[std::size_t(at)].begin = begin, nodes[std::size_t(at)].end = end;
      return at;
    }
    // SAH splits while the levels left allow any; median splits, which need the fewest, after
    // (a scene whose objects grow geometrically in size and spacing would peel a few off per
    // level, as bvh.cpp's builder guards against too).
    const bool median = depth + 1 + levels_needed(end - begin) >= max_depth;
    const std::uint32_t mid = split(begin, end, median);
    const int left = build(begin, mid, depth + 1);
    const int right = build(mid, end, depth + 1);
    nodes[std::size_t(at)].left = left, nodes[std::size_t(at)].right = right;
    return at;
  }
};

item sphere_item(const gpu::gpu_sphere& s, const glm::vec4* velocity, float t0, float t1,
                 std::uint32_t k) {
  item it{{}, {}, packet_bvh::sphere_kind, k};
  const real3 r(s.radius);
  for (const float time : {t0, t1}) {
    const real3 c = velocity ? moved_center(s.center, real3(*velocity), time) : real3(s.center);
    it.b.grow(c - r), it.b.grow(c + r);
  }
  return it;
}

}  // namespace

packet_bvh::packet_bvh(const gpu::scene_arrays& a, std::uint32_t spheres,
                       const std::vector<quad_geometry>& quads, std::uint32_t quad_count,
                       const std::vector<disk_geometry>& disks, std::uint32_t disk_count,
                       float motion_begin, float motion_end) {
  const bool moves = !a.velocities.empty();
  builder bd;
  for (std::uint32_t k = 0; k < spheres; ++k)
    bd.items.push_back(
        sphere_item(a.spheres[k], moves ? &a.velocities[k] : nullptr, motion_begin, motion_end, k));
  for (std::uint32_t k = 0; k < quad_count; ++k) {
    const quad_geometry& q = quads[k];
    item it{{}, {}, quad_kind, k};
    for (const real3 p : {q.Q, q.Q + q.u, q.Q + q.v, q.Q + q.u + q.v}) it.b.grow(p);
    bd.items.push_back(it);
  }
  for (std::uint32_t k = 0; k < disk_count; ++k) {
    item it{{}, {}, disk_kind, k};
    it.b.grow(disks[k].center - real3(disks[k].radius));
    it.b.grow(disks[k].center + real3(disks[k].radius));
    bd.items.push_back(it);
  }
  if (bd.items.empty()) return;
  for (item& it : bd.items) {
    it.b = grown(it.b);
    for (int k = 0; k < 3; ++k) it.c[k] = 0.5f * (it.b.lo[k] + it.b.hi[k]);
  }
  bd.build(0, std::uint32_t(bd.items.size()), 0);

  // A leaf's objects, lane by lane, in a new packet of their kind: its child reference.
  const auto pack = [&](const binary_node& leaf) -> std::uint32_t {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::uint32_t kind = bd.items[leaf.begin].kind;
    std::uint32_t packet = 0;
    for (std::uint32_t l = 0; l < lanes; ++l) {
      const bool used = leaf.begin + l < leaf.end;
      const std::uint32_t k = used ? bd.items[leaf.begin + l].index : 0;
      if (kind == sphere_kind) {
        if (l == 0) {
          packet = std::uint32_t(spheres_.size()), spheres_.emplace_back();
          if (moves) motions_.emplace_back();
        }
        sphere_packet& p = spheres_.back();
        const gpu::gpu_sphere& s = a.spheres[k];
        p.x[l] = s.center.x, p.y[l] = s.center.y, p.z[l] = s.center.z;
        p.radius[l] = used ? s.radius : nan;
        p.index[l] = k, p.key[l] = s.scene_index;
        if (moves) {
          const glm::vec4 v = a.velocities[k];
          motions_.back().vx[l] = v.x, motions_.back().vy[l] = v.y, motions_.back().vz[l] = v.z;
        }
      } else if (kind == quad_kind) {
        if (l == 0) packet = std::uint32_t(quads_.size()), quads_.emplace_back();
        quad_packet& p = quads_.back();
        const quad_geometry& q = quads[k];
        p.qx[l] = q.Q.x, p.qy[l] = q.Q.y, p.qz[l] = q.Q.z;
        p.ux[l] = q.u.x, p.uy[l] = q.u.y, p.uz[l] = q.u.z;
        p.vx[l] = q.v.x, p.vy[l] = q.v.y, p.vz[l] = q.v.z;
        p.nx[l] = q.normal.x, p.ny[l] = q.normal.y, p.nz[l] = q.normal.z;
        p.d[l] = used ? q.D : nan;
        p.wx[l] = q.w.x, p.wy[l] = q.w.y, p.wz[l] = q.w.z;
        p.index[l] = k, p.key[l] = a.quads[k].scene_index;
      } else {
        if (l == 0) packet = std::uint32_t(disks_.size()), disks_.emplace_back();
        disk_packet& p = disks_.back();
        const disk_geometry& g = disks[k];
        p.x[l] = g.center.x, p.y[l] = g.center.y, p.z[l] = g.center.z;
        p.radius[l] = g.radius;
        p.nx[l] = g.normal.x, p.ny[l] = g.normal.y, p.nz[l] = g.normal.z;
        p.d[l] = used ? g.D : nan;
        p.index[l] = k, p.key[l] = a.disks[k].scene_index;
      }
    }
    return leaf_bit | (kind << kind_shift) | packet;
  };

  // Collapses binary node b and its descendants into wide nodes: each takes the children of its
  // largest interior children until it has four. Returns the wide node's index.
  const auto collapse = [&](auto&& self, int b, int level) -> std::uint32_t {
    levels_ = std::max(levels_, level);
    if (level > max_levels)  // the builder's max_depth rules it out
      throw std::logic_error("packet_bvh: the tree is too deep");
    std::vector<int> children;
    const binary_node& root = bd.nodes[std::size_t(b)];
    if (root.left < 0)
      children = {b};  // a root that is a leaf: one child
    else
      children = {root.left, root.right};
    while (children.size() < lanes) {
      int widest = -1;
      double area = -1;
      for (std::size_t c = 0; c < children.size(); ++c) {
        const binary_node& n = bd.nodes[std::size_t(children[c])];
        if (n.left >= 0 && n.b.half_area() > area) area = n.b.half_area(), widest = int(c);
      }
      if (widest < 0) break;
      const binary_node& n = bd.nodes[std::size_t(children[std::size_t(widest)])];
      children[std::size_t(widest)] = n.left;
      children.push_back(n.right);
    }
    const std::uint32_t at = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    node w{};
    for (int k = 0; k < 3; ++k)
      w.planes[k] = f4{inf, inf, inf, inf}, w.planes[3 + k] = -w.planes[k];
    for (std::uint32_t c = 0; c < lanes; ++c) w.child[c] = none;
    for (std::size_t c = 0; c < children.size(); ++c) {
      const binary_node& n = bd.nodes[std::size_t(children[c])];
      for (int k = 0; k < 3; ++k) w.planes[k][c] = n.b.lo[k], w.planes[3 + k][c] = n.b.hi[k];
      w.child[c] = n.left < 0 ? pack(n) : self(self, children[c], level + 1);
      w.lanes |= 1u << c;
    }
    nodes_[at] = w;
    return at;
  };
  collapse(collapse, 0, 1);
}

}  // namespace rtvk::fast
