// packet_bvh's search: the nearest child first, four boxes per slab test, four objects per leaf
// test. The leaf tests are the kernels' tests lane by lane (hit_sphere.h, hit_quad.h,
// hit_disk.h): the same float operations in the same order, so the same bits.
#include <xmmintrin.h>

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
// Lane masks (-1 or 0 per lane, GCC's comparisons) as the four bits of a number.
template <typename M>
inline int bits(M m) {
  return _mm_movemask_ps(reinterpret_cast<__m128>(m));
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
  f4 ix, iy, iz;        // 1 / direction, zeros replaced by a tiny signed value
  f4 lo_x, lo_y, lo_z;  // the origin less the slab test's margin, and plus it
  f4 hi_x, hi_y, hi_z;
  f4 a;  // dot3(direction, direction), hit_sphere's a

  explicit ray_lanes(const ray& r) {
    ox = splat(r.origin.x), oy = splat(r.origin.y), oz = splat(r.origin.z);
    dx = splat(r.direction.x), dy = splat(r.direction.y), dz = splat(r.direction.z);
    time = splat(r.time);
    const auto inverse = [](float d) {
      return 1.0f / (std::abs(d) < 1e-20f ? std::copysign(1e-20f, d) : d);
    };
    ix = splat(inverse(r.direction.x)), iy = splat(inverse(r.direction.y));
    iz = splat(inverse(r.direction.z));
    // Rounding the origin to float and subtracting it from a corner err by half an ulp of its
    // largest coordinate each: 2^-20 of it (16 ulps) is added to every box (bvh.h's
    // origin_margin), so the slab test never culls a box the ray enters.
    const float m =
        std::max({std::abs(r.origin.x), std::abs(r.origin.y), std::abs(r.origin.z)}) * 0x1p-20f;
    lo_x = ox + splat(m), lo_y = oy + splat(m), lo_z = oz + splat(m);
    hi_x = ox - splat(m), hi_y = oy - splat(m), hi_z = oz - splat(m);
    a = splat(dot3(r.direction, r.direction));
  }
};

template <bool any>
bool packet_bvh::search(const ray& r, real t_min, real t_max, found& f) const {
  if (nodes_.empty()) return false;
  const ray_lanes l(r);
  const f4 near = splat(t_min);
  f4 far = splat(t_max);
  bool hit = false;
  std::uint32_t best_key = 0;
  // Keeps lane `lane` of a packet that hit at t when nearer, or as near and later in the scene.
  const auto offer = [&](std::uint32_t kind, std::uint32_t index, std::uint32_t key, float t) {
    if (hit && !(t < f.t || (t == f.t && key > best_key))) return;
    hit = true, f.kind = kind, f.index = index, f.t = t, best_key = key;
    far = splat(t);
  };
  struct entry {
    std::uint32_t ref;
    float t;  // where the ray enters the child's box
  };
  entry stack[3 * max_levels + 4];
  int top = 0;
  stack[top++] = {0, t_min};
  while (top > 0) {
    const entry e = stack[--top];
    if (hit && e.t > f.t) continue;  // a nearer hit was found since it was remembered
    if ((e.ref & leaf_bit) == 0) {
      const node& n = nodes_[e.ref];
      const f4 x0 = (n.lo[0] - l.lo_x) * l.ix, x1 = (n.hi[0] - l.hi_x) * l.ix;
      const f4 y0 = (n.lo[1] - l.lo_y) * l.iy, y1 = (n.hi[1] - l.hi_y) * l.iy;
      const f4 z0 = (n.lo[2] - l.lo_z) * l.iz, z1 = (n.hi[2] - l.hi_z) * l.iz;
      const f4 enter = vmax(vmax(vmin(x0, x1), vmin(y0, y1)), vmax(vmin(z0, z1), near));
      const f4 leave = vmin(vmin(vmax(x0, x1), vmax(y0, y1)), vmin(vmax(z0, z1), far));
      int mask = bits(enter <= leave) & int(n.lanes);
      // The children entered, sorted on the stack farthest first so that the nearest is searched
      // next (in place: a copy from a local array became a slow `rep movs`).
      const int base = top;
      while (mask != 0) {
        const int c = __builtin_ctz(unsigned(mask));
        mask &= mask - 1;
        const entry in{n.child[c], enter[c]};
        int k = top++;
        for (; k > base && stack[k - 1].t < in.t; --k) stack[k] = stack[k - 1];
        stack[k] = in;
      }
      continue;
    }
    const std::uint32_t kind = (e.ref >> kind_shift) & 3u, at = e.ref & packet_mask;
    int mask;
    f4 t;
    if (kind == sphere_kind) {  // hit_sphere.h's hit_sphere
      const sphere_packet& p = spheres_[at];
      f4 cx = p.x, cy = p.y, cz = p.z;
      if (moves_) cx = p.x + l.time * p.vx, cy = p.y + l.time * p.vy, cz = p.z + l.time * p.vz;
      const f4 ocx = l.ox - cx, ocy = l.oy - cy, ocz = l.oz - cz;
      const f4 half_b = ocx * l.dx + ocy * l.dy + ocz * l.dz;
      const f4 k = half_b / l.a;
      const f4 lx = ocx - k * l.dx, ly = ocy - k * l.dy, lz = ocz - k * l.dz;
      const f4 disc = l.a * (p.radius * p.radius - (lx * lx + ly * ly + lz * lz));
      const auto real_roots = (disc >= splat(0)) & (disc < splat(inf));
      const f4 sqrtd = reinterpret_cast<f4>(_mm_sqrt_ps(reinterpret_cast<__m128>(disc)));
      const f4 near_root = (-half_b - sqrtd) / l.a, far_root = (-half_b + sqrtd) / l.a;
      const auto near_in = in_range(near_root, near, far);
      const auto far_in = in_range(far_root, near, far);
      t = near_in ? near_root : far_root;
      mask = bits(real_roots & (near_in | far_in));
    } else if (kind == quad_kind) {  // hit_quad.h's hit_quad
      const quad_packet& p = quads_[at];
      const f4 denom = p.nx * l.dx + p.ny * l.dy + p.nz * l.dz;
      const auto facing = (denom >= splat(1e-8f)) | (denom <= splat(-1e-8f));
      t = (p.d - (p.nx * l.ox + p.ny * l.oy + p.nz * l.oz)) / denom;
      const f4 px = (l.ox + t * l.dx) - p.qx, py = (l.oy + t * l.dy) - p.qy,
               pz = (l.oz + t * l.dz) - p.qz;
      const f4 alpha = p.wx * (py * p.vz - pz * p.vy) + p.wy * (pz * p.vx - px * p.vz) +
                       p.wz * (px * p.vy - py * p.vx);
      const f4 beta = p.wx * (p.uy * pz - p.uz * py) + p.wy * (p.uz * px - p.ux * pz) +
                      p.wz * (p.ux * py - p.uy * px);
      mask = bits(facing & in_range(t, near, far) & (alpha >= splat(0)) & (alpha <= splat(1)) &
                  (beta >= splat(0)) & (beta <= splat(1)));
    } else {  // hit_disk.h's hit_disk
      const disk_packet& p = disks_[at];
      const f4 denom = p.nx * l.dx + p.ny * l.dy + p.nz * l.dz;
      const auto facing = (denom >= splat(1e-8f)) | (denom <= splat(-1e-8f));
      t = (p.d - (p.nx * l.ox + p.ny * l.oy + p.nz * l.oz)) / denom;
      const f4 px = (l.ox + t * l.dx) - p.x, py = (l.oy + t * l.dy) - p.y,
               pz = (l.oz + t * l.dz) - p.z;
      mask = bits(facing & in_range(t, near, far) &
                  ((px * px + py * py + pz * pz) <= p.radius * p.radius));
    }
    if (mask == 0) continue;
    if (any) return true;
    const std::uint32_t* index = kind == sphere_kind ? spheres_[at].index
                                 : kind == quad_kind ? quads_[at].index
                                                     : disks_[at].index;
    const std::uint32_t* key = kind == sphere_kind ? spheres_[at].key
                               : kind == quad_kind ? quads_[at].key
                                                   : disks_[at].key;
    while (mask != 0) {
      const int c = __builtin_ctz(unsigned(mask));
      mask &= mask - 1;
      offer(kind, index[c], key[c], t[c]);
    }
  }
  return hit;
}

bool packet_bvh::hit(const ray& r, real t_min, real t_max, found& f) const {
  return search<false>(r, t_min, t_max, f);
}

bool packet_bvh::blocked(const ray& r, real t_min, real t_max) const {
  found f;
  return search<true>(r, t_min, t_max, f);
}

}  // namespace rtvk::fast
