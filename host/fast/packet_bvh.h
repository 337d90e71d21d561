#pragma once
// The fast mode's own search for the world's spheres, quads and disks: a four-wide BVH whose
// leaves hold up to four objects of one kind side by side (a packet), tested four at once in SSE
// registers. Embree tests these shapes one callback at a time; a packet does in one pass what
// four callbacks did. Each lane does the float operations of the shared kernels' test
// (hit_sphere.h, hit_quad.h, hit_disk.h) in their order, so a lane's hit and t are the kernel's
// bit for bit (tests/cpu/test_packet_bvh.cpp), and exact ties go to the later scene index, the
// GPU's rule. Only the fast mode's translation units include this header (float kernels).
#include <cstdint>
#include <vector>

#include "hit_disk.h"
#include "hit_quad.h"
#include "hit_sphere.h"
#include "scene_arrays.h"

namespace rtvk::fast {

class packet_bvh {
 public:
  // Four floats in one SSE register (GCC and Clang's vector extension), a lane per object.
  using f4 = float __attribute__((vector_size(16)));

  // The kinds of object, numbered as world::kind numbers them.
  enum kind : std::uint32_t { sphere_kind, quad_kind, disk_kind, kinds };

  // The nearest hit a search found: the object's kind, its place in its array, and t.
  struct found {
    std::uint32_t kind = 0, index = 0;
    real t = 0;
  };

  // Over the first spheres, quads and disks of the arrays (the world's own objects); quads and
  // disks as the kernels read them. Moving spheres are bounded over [motion_begin, motion_end].
  packet_bvh(const gpu::scene_arrays& a, std::uint32_t spheres,
             const std::vector<quad_geometry>& quads, std::uint32_t quad_count,
             const std::vector<disk_geometry>& disks, std::uint32_t disk_count, float motion_begin,
             float motion_end);

  bool empty() const { return nodes_.empty(); }
  // The nearest hit at t in [t_min, t_max], exact ties to the later scene index.
  bool hit(const ray& r, real t_min, real t_max, found& f) const;
  // Whether anything is hit at t in [t_min, t_max].
  bool blocked(const ray& r, real t_min, real t_max) const;

  // Four objects' data side by side; an unused lane holds NaN, which no test passes.
  struct sphere_packet {
    f4 x, y, z, radius;              // centers at time 0 and radii, scene units
    std::uint32_t index[4], key[4];  // place in the arrays; scene index (ties)
  };
  // A sphere packet's velocities, scene units per second: kept apart, so that scenes where
  // nothing moves read no more than the spheres.
  struct sphere_motion {
    f4 vx, vy, vz;
  };
  struct quad_packet {
    f4 qx, qy, qz, ux, uy, uz, vx, vy, vz;  // a corner and both edges
    f4 nx, ny, nz, d;                       // unit normal, dot(normal, Q)
    f4 wx, wy, wz;                          // cross(u, v) / |cross(u, v)|^2
    std::uint32_t index[4], key[4];
  };
  struct disk_packet {
    f4 x, y, z, radius;  // center and radius
    f4 nx, ny, nz, d;    // unit normal, dot(normal, center)
    std::uint32_t index[4], key[4];
  };

  // Four children's boxes side by side, and per child an interior node's index, a leaf (leaf_bit
  // | kind << kind_shift | packet index), or none.
  struct node {
    f4 planes[6];  // lo x, y, z, then hi x, y, z; lanes by child; scene units (grown for float
                   // rounding)
    std::uint32_t child[4];
    std::uint32_t lanes;  // bit c: child c is in use
  };
  static constexpr std::uint32_t leaf_bit = 0x80000000u, kind_shift = 29, none = ~0u;
  static constexpr std::uint32_t packet_mask = (1u << kind_shift) - 1u;
  // Most wide levels a tree may have: its traversal stack holds three children per level.
  static constexpr int max_levels = 48;

  const std::vector<node>& nodes() const { return nodes_; }
  int levels() const { return levels_; }

 private:
  struct ray_lanes;
  template <bool any>
  struct walker;
  template <bool any>
  bool search(const ray& r, real t_min, real t_max, found& f) const;
  template <bool any, typename Offer>
  bool test_leaf(std::uint32_t ref, const ray_lanes& l, f4 near, f4 far, Offer&& offer) const;

  std::vector<node> nodes_;  // node 0 the root; empty without objects
  std::vector<sphere_packet> spheres_;
  std::vector<sphere_motion> motions_;  // by sphere packet; empty when no sphere moves
  std::vector<quad_packet> quads_;
  std::vector<disk_packet> disks_;
  int levels_ = 0;  // wide levels on the longest path
};

}  // namespace rtvk::fast
