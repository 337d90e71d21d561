#pragma once
// The fast mode's world: the scene's arrays (scene_arrays.h, the GPU's own) behind Embree. Only
// the fast mode's translation units include this header: they compile the shared kernels with
// float as `real` in namespace rtvk::fast (host/fast/CMakeLists.txt), as the GPU does.
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "hit_disk.h"
#include "hit_quad.h"
#include "hit_sphere.h"
#include "hit_triangle.h"
#include "instance_space.h"
#include "packet_bvh.h"
#include "scene_arrays.h"

namespace rtvk::fast {

// Two searches find the nearest hit. The world's own spheres, quads and disks are packet_bvh's:
// the kernels' own tests, four objects at once, so their hits are the GPU's bit for bit and
// exact ties go to the later scene index, as on the GPU. Triangles and instances are Embree's:
// its triangle test, and callbacks that run the kernels' tests in an instanced group's tree
// (quads there are Embree's); it searches up to the packets' hit and wins an exact tie with it
// (the GPU gives instances such ties, as objects later in the scan; a triangle's t differs from
// the GPU's by rounding anyway). A winner's record is then made by the kernels as world.glsl makes
// it (record_winner); Embree's hits differ from the GPU's by float rounding of t (a few ulps of
// the distance), which the image tests measure.
class world {
 public:
  // Over the arrays (which must outlive the world), moving spheres bounded over
  // [motion_begin, motion_end] (the scene's time_span).
  world(const gpu::scene_arrays& a, float motion_begin, float motion_end);
  ~world();
  world(const world&) = delete;
  world& operator=(const world&) = delete;

  // The nearest hit at t in [t_min, t_max]: rec as the GPU records it.
  bool hit(const ray& r, real t_min, real t_max, hit_record& rec) const;
  // Whether anything is hit at t in [t_min, t_max] (a shadow ray that every hit blocks).
  bool blocked(const ray& r, real t_min, real t_max) const;

  // Shape kinds as the Embree geometries of each tree are numbered (their geometry ids).
  enum kind : unsigned { sphere_kind, quad_kind, disk_kind, triangle_kind, instance_kind, kinds };
  // One tree: the world's own objects, or an instanced group's. Its objects of each kind are a
  // run of the arrays: [first[k], first[k] + count[k]).
  struct tree {
    RTCScene scene = nullptr;
    std::array<std::uint32_t, kinds> first{}, count{};
    bool packed = false;  // its spheres, quads and disks are packet_bvh's, not Embree's
  };
  // What a callback reads: the world and the tree whose geometry called.
  struct geometry_data {
    const world* w;
    const tree* t;
  };

  // The arrays as the kernels read them (quad_geometry and the others, in float).
  const gpu::scene_arrays& arrays;
  std::vector<quad_geometry> quads;
  std::vector<disk_geometry> disks;
  std::vector<instance_frame> frames;        // by instance
  std::vector<std::uint32_t> instance_tree;  // by instance: its group's tree in `trees`
  std::vector<tree> trees;                   // [0]: the world's own; then one per group
  std::unique_ptr<packet_bvh> packets;       // the world's own spheres, quads and disks
  bool embree_world = false;                 // Embree's world tree holds something (triangles
                                             // or instances)
  bool moves = false;                        // some sphere has a velocity
  bool any_triangles = false;                // shear rays for the triangles' records
  float motion_begin = 0, motion_end = 0;    // the scene's time span, seconds

 private:
  void build_tree(tree& t);
  bool native(unsigned k) const;
  void attach(tree& t, RTCGeometry g, unsigned id);
  void record(const RTCRayHit& h, const ray& r, hit_record& rec) const;
  void record_in(const tree& t, const RTCHit& hit, const ray& r, real t_hit, hit_record& rec) const;
  bool finish(const ray& r, real t_min, real t_max, bool own, const packet_bvh::found& f,
              hit_record& rec) const;
  void record_own(const packet_bvh::found& f, const ray& r, hit_record& rec) const;

  RTCDevice device_ = nullptr;
  std::vector<geometry_data> data_;  // one per user geometry, kept where Embree points
};

// The shared kernels' ray from Embree's, and back.
inline ray ray_of(const RTCRay& e) {
  return ray(real3(e.org_x, e.org_y, e.org_z), real3(e.dir_x, e.dir_y, e.dir_z), e.time);
}
RTCRayHit embree_ray(const ray& r, real t_min, real t_max);

}  // namespace rtvk::fast
