// packet_bvh's search: the nearest child first, four boxes per slab test, four objects per leaf
// test. The leaf tests are the kernels' tests lane by lane (hit_sphere.h, hit_quad.h,
// hit_disk.h): the same float operations in the same order, so the same bits.
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>

#include "packet_bvh.h"

namespace rtvk::fast {
namespace {

using f4 = packet_bvh::f4;
constexpr float inf = std::numeric_limits<float>::infinity();

inline f4 splat(float v) {
  return f4{v, v, v, v};
}
// Lane masks (-1 or 0 per lane, GCC's comparisons) as the four bits of a number, and the
// square roots of four lanes: SSE's where there is SSE, lane by lane elsewhere (the same bits).
template <typename M>
inline int bits(M m) {
#if defined(__SSE2__)
  return _mm_movemask_ps(reinterpret_cast<__m128>(m));
#else
  return int(m[0] & 1) | int(m[1] & 1) << 1 | int(m[2] & 1) << 2 | int(m[3] & 1) << 3;
#endif
}
inline f4 vsqrt(f4 x) {
#if defined(__SSE2__)
  return reinterpret_cast<f4>(_mm_sqrt_ps(reinterpret_cast<__m128>(x)));
#else
  return f4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}
inline f4 vmin(f4 a, f4 b) {
  return a < b ? a : b;
}
inline f4 vmax(f4 a, f4 b) {
  return a > b ? a : b;
}

// The kernels' `is_finite(root) && t_min <= root && root <= t_max`, per lane (t_min is finite,
// so root >= t_min rules out NaN and minus infinity, root < inf plus infinity).
template <typename M = decltype(f4{} < f4{})>
inline M in_range(f4 root, f4 t_min, f4 t_max) {
  return (root >= t_min) & (root <= t_max) & (root < splat(inf));
}

}  // namespace

// A ray as every lane reads it: each component in all four.
struct packet_bvh::ray_lanes {
  f4 ox, oy, oz, dx, dy, dz, time;
  f4 inv[3];  // 1 / direction, zeros replaced by a tiny signed value
  f4 o_near[3],
      o_far[3];       // the origin moved by the slab test's margin, for the near and far planes
  int near_plane[3];  // per axis: 0 when the ray enters a box by its low face, 3 by its high
  f4 a;               // dot3(direction, direction), hit_sphere's a

  explicit ray_lanes(const ray& r) {
    ox = splat(r.origin.x), oy = splat(r.origin.y), oz = splat(r.origin.z);
    dx = splat(r.direction.x), dy = splat(r.direction.y), dz = splat(r.direction.z);
    time = splat(r.time);
    // The slab test's margin for the ray's side, and its inverse direction, as accel/bvh.h's
    // origin_margin and safe_inverse make them (that header brings the double kernels, which
    // this translation unit's float ones would clash with): rounding the origin to float and
    // subtracting it from a corner err by half an ulp of its largest coordinate each, so 2^-20
    // of it (16 ulps) is added to every box, and the slab test never culls a box the ray enters.
    const float m =
        std::max({std::abs(r.origin.x), std::abs(r.origin.y), std::abs(r.origin.z)}) * 0x1p-20f;
    for (int k = 0; k < 3; ++k) {
      const float d = r.direction[k];
      inv[k] = splat(1.0f / (std::abs(d) < 1e-20f ? std::copysign(1e-20f, d) : d));
      const bool down = inv[k][0] < 0;  // enters by the high face
      near_plane[k] = down ? 3 : 0;
      o_near[k] = splat(down ? r.origin[k] - m : r.origin[k] + m);
      o_far[k] = splat(down ? r.origin[k] + m : r.origin[k] - m);
    }
    a = splat(dot3(r.direction, r.direction));
  }
};

namespace {

// Where the ray enters each of n's four boxes (lanes), and which of them it enters within
// [near, far] (bits).
template <typename Node, typename Lanes>
inline int entries(const Node& n, const Lanes& l, f4 near, f4 far, f4& enter) {
  const f4* planes = n.planes;
  enter = near;
  f4 leave = far;
  for (int k = 0; k < 3; ++k) {
    enter = vmax(enter, (planes[l.near_plane[k] + k] - l.o_near[k]) * l.inv[k]);
    leave = vmin(leave, (planes[3 - l.near_plane[k] + k] - l.o_far[k]) * l.inv[k]);
  }
  return bits(enter <= leave) & int(n.lanes);
}

// The quad's and the disk's way to their plane (hit_quad.h, hit_disk.h): t where the ray meets
// each lane's plane (unit normal n, dot(n, x) = d), the point there less `at` (a corner, a
// center), and which lanes face the ray enough and meet it within [near, far].
template <typename Lanes>
inline int plane_hit(const Lanes& l, f4 nx, f4 ny, f4 nz, f4 d, f4 ax, f4 ay, f4 az, f4 near,
                     f4 far, f4& t, f4& px, f4& py, f4& pz) {
  const f4 denom = nx * l.dx + ny * l.dy + nz * l.dz;
  const auto facing = (denom >= splat(1e-8f)) | (denom <= splat(-1e-8f));
  t = (d - (nx * l.ox + ny * l.oy + nz * l.oz)) / denom;
  px = (l.ox + t * l.dx) - ax, py = (l.oy + t * l.dy) - ay, pz = (l.oz + t * l.dz) - az;
  return bits(facing & in_range(t, near, far));
}

}  // namespace

// Tests the objects of leaf `ref`, offering each lane's hit (offer: kind, index, key, t). True
// when `any` and something is hit.
template <bool any, typename Offer>
inline bool packet_bvh::test_leaf(std::uint32_t ref, const ray_lanes& l, f4 near, f4 far,
                                  Offer&& offer) const {
  const std::uint32_t kind = (ref >> kind_shift) & 3u, at = ref & packet_mask;
  int mask;
  f4 t;
  const std::uint32_t *index, *key;
  if (kind == sphere_kind) {  // hit_sphere.h's hit_sphere
    const sphere_packet& p = spheres_[at];
    f4 cx = p.x, cy = p.y, cz = p.z;
    if (!motions_.empty()) {
      const sphere_motion& v = motions_[at];
      cx = p.x + l.time * v.vx, cy = p.y + l.time * v.vy, cz = p.z + l.time * v.vz;
    }
    const f4 ocx = l.ox - cx, ocy = l.oy - cy, ocz = l.oz - cz;
    const f4 half_b = ocx * l.dx + ocy * l.dy + ocz * l.dz;
    const f4 k = half_b / l.a;
    const f4 lx = ocx - k * l.dx, ly = ocy - k * l.dy, lz = ocz - k * l.dz;
    const f4 disc = l.a * (p.radius * p.radius - (lx * lx + ly * ly + lz * lz));
    const auto real_roots = (disc >= splat(0)) & (disc < splat(inf));
    const f4 sqrtd = vsqrt(disc);
    const f4 near_root = (-half_b - sqrtd) / l.a, far_root = (-half_b + sqrtd) / l.a;
    const auto near_in = in_range(near_root, near, far);
    const auto far_in = in_range(far_root, near, far);
    t = near_in ? near_root : far_root;
    mask = bits(real_roots & (near_in | far_in));
    index = p.index, key = p.key;
  } else if (kind == quad_kind) {  // hit_quad.h's hit_quad
    const quad_packet& p = quads_[at];
    f4 px, py, pz;
    mask = plane_hit(l, p.nx, p.ny, p.nz, p.d, p.qx, p.qy, p.qz, near, far, t, px, py, pz);
    const f4 alpha = p.wx * (py * p.vz - pz * p.vy) + p.wy * (pz * p.vx - px * p.vz) +
                     p.wz * (px * p.vy - py * p.vx);
    const f4 beta = p.wx * (p.uy * pz - p.uz * py) + p.wy * (p.uz * px - p.ux * pz) +
                    p.wz * (p.ux * py - p.uy * px);
    mask &=
        bits((alpha >= splat(0)) & (alpha <= splat(1)) & (beta >= splat(0)) & (beta <= splat(1)));
    index = p.index, key = p.key;
  } else {  // hit_disk.h's hit_disk
    const disk_packet& p = disks_[at];
    f4 px, py, pz;
    mask = plane_hit(l, p.nx, p.ny, p.nz, p.d, p.x, p.y, p.z, near, far, t, px, py, pz);
    mask &= bits((px * px + py * py + pz * pz) <= p.radius * p.radius);
    index = p.index, key = p.key;
  }
  if (any) return mask != 0;
  for (; mask != 0; mask &= mask - 1) {
    const int c = __builtin_ctz(unsigned(mask));
    offer(kind, index[c], key[c], t[c]);
  }
  return false;
}

// One ray's search in progress: step() takes it one node or one leaf further. The nearest
// child a node's test enters is searched next; the others are remembered with where the ray
// enters them, and dropped when they come up behind the nearest hit found since.
template <bool any>
struct packet_bvh::walker {
  struct entry {
    std::uint32_t ref;
    float t;  // where the ray enters the child's box
  };
  const packet_bvh& tree;
  const ray_lanes l;
  const f4 near;
  f4 far;
  float reach;  // the nearest hit so far, or t_max
  bool hit = false;
  std::uint32_t best_key = 0;
  found f;
  entry stack[3 * max_levels + 4];
  int top = 0;
  std::uint32_t next = 0;  // the root

  walker(const packet_bvh& b, const ray& r, real t_min, real t_max)
      : tree(b), l(r), near(splat(t_min)), far(splat(t_max)), reach(t_max) {}

  // Keeps a lane's hit at t when nearer, or as near and later in the scene.
  void offer(std::uint32_t kind, std::uint32_t index, std::uint32_t key, float t) {
    if (hit && !(t < f.t || (t == f.t && key > best_key))) return;
    hit = true, f.kind = kind, f.index = index, f.t = t, best_key = key;
    reach = t, far = splat(t);
  }

  // False when the search is over: `hit`, and f the nearest hit when there is one (with `any`,
  // hit says that something blocks the ray).
  bool step() {
    if ((next & leaf_bit) == 0) {
      const node& n = tree.nodes_[next];
      f4 enter;
      int mask = entries(n, l, near, far, enter);
      if (mask != 0) {
        int c = __builtin_ctz(unsigned(mask));
        mask &= mask - 1;
        if (mask == 0) {
          next = n.child[c];
          return true;
        }
        const int base = top;  // sorted on the stack, farthest deepest
        for (;; c = __builtin_ctz(unsigned(mask)), mask &= mask - 1) {
          const entry in{n.child[c], enter[c]};
          int k = top++;
          for (; k > base && stack[k - 1].t < in.t; --k) stack[k] = stack[k - 1];
          stack[k] = in;
          if (mask == 0) break;
        }
        next = stack[--top].ref;
        return true;
      }
    } else if (tree.test_leaf<any>(
                   next, l, near, far,
                   [this](std::uint32_t kind, std::uint32_t index, std::uint32_t key, float t) {
                     offer(kind, index, key, t);
                   })) {
      hit = true;  // `any`: something blocks the ray
      return false;
    }
    while (top > 0 && stack[top - 1].t > reach) --top;
    if (top == 0) return false;
    next = stack[--top].ref;
    return true;
  }
};

template <bool any>
bool packet_bvh::search(const ray& r, real t_min, real t_max, found& f) const {
  if (nodes_.empty()) return false;
  walker<any> w(*this, r, t_min, t_max);
  while (w.step()) {
  }
  f = w.f;
  return w.hit;
}

bool packet_bvh::hit(const ray& r, real t_min, real t_max, found& f) const {
  return search<false>(r, t_min, t_max, f);
}

bool packet_bvh::blocked(const ray& r, real t_min, real t_max) const {
  found f;
  return search<true>(r, t_min, t_max, f);
}

}  // namespace rtvk::fast
