#pragma once
#include <array>
#include <span>
#include <vector>

#include "bvh.h"
#include "hit_disk.h"
#include "hit_quad.h"
#include "hit_triangle.h"
#include "hittable.h"
#include "instance_space.h"
#include "scene.h"
#include "scene_tree.h"
#include "sphere.h"
#include "wide_bvh.h"

namespace rtvk {

// The scene's objects behind a BVH (accel/bvh.h): hits are identical to a linear scan over the
// objects in order (spheres, quads, triangles) -- the nearest root wins, and on an exact tie the
// later object in the scene, as in hittable_list.
class bvh_world final : public hittable {
 public:
  // Built on `threads` threads (0: one per core), bounding moving spheres over `motion`.
  explicit bvh_world(const std::vector<sphere>& spheres, int threads = 0, time_span motion = {});
  // Over objects of every kind; `shading` holds what the triangles' shading indices refer to.
  bvh_world(const primitive_spans& objects, std::span<const triangle_shading> shading,
            int threads = 0, time_span motion = {});
  // Over a scene's objects and its instances (a tree per group, one over the instances).
  explicit bvh_world(const scene& s, int threads = 0);

  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const override;
  // As hit, and which object won: `object`, its place in the scan order (the scene index of the
  // world's own, spheres then quads then triangles; an instance's object its place in its
  // group), and `instance`, the instance + 1 it was reached through (0: the world's own).
  bool hit_which(const ray& r, double t_min, double t_max, hit_record& rec, std::uint32_t& object,
                 std::uint32_t& instance) const;

 private:
  struct nearest;
  void build(const primitive_spans& objects, std::span<const triangle_shading> shading,
             std::span<const object_group> groups, std::span<const instance> instances, int threads,
             time_span motion);
  void walk(std::uint32_t root, const ray& r, const sheared_ray& sheared, double t_min,
            nearest& best, std::int64_t instance) const;
  void enter(std::uint32_t instance, const ray& r, double t_min, nearest& best) const;
  void visit(std::uint32_t ref, const ray& r, const sheared_ray& sheared, double t_min,
             nearest& best) const;
  [[gnu::noinline]] void visit_flat(std::uint32_t ref, const ray& r, const sheared_ray& sheared,
                                    double t_min, nearest& best) const;
  void record(const nearest& best, const ray& r, const sheared_ray& sheared, hit_record& rec) const;

  // A sphere as the search reads it: what a still one needs, in 40 bytes (a moving one's
  // velocity is kept apart, so scenes where nothing moves read no more than before).
  struct leaf_sphere {
    point3 center;  // at time 0, scene units
    double radius;  // scene units
    int material;   // index into the scene's materials
  };

  // A quad with its plane, and a triangle with its vertices, as the search reads them.
  struct leaf_quad {
    quad_geometry g;  // the book's precomputed quad
    int material;     // index into the scene's materials
  };
  struct leaf_triangle {
    std::array<point3, 3> p;  // vertices, scene units
    int material;             // index into the scene's materials
    std::int32_t shading;     // index into attributes_, or -1: flat, uv barycentric
  };
  struct leaf_disk {
    disk_geometry g;  // its plane and axes
    int material;     // index into the scene's materials
  };

  // The binary tree (the GPU's) is built, collapsed and dropped: the CPU keeps only these. Each
  // kind's array is in leaf order (leaf_layout); *_index_ give each position's scene index.
  std::vector<wide_node> nodes_;          // the trees collapsed four wide (scene_tree)
  std::vector<leaf_sphere> spheres_;      // in leaf order
  std::vector<vec3> velocities_;          // the spheres', in leaf order; empty when none moves
  std::vector<leaf_quad> quads_;          // in leaf order
  std::vector<leaf_triangle> triangles_;  // in leaf order
  std::vector<leaf_disk> disks_;          // in leaf order
  std::vector<triangle_attributes> attributes_;  // triangles' vertex normals and uv
  std::vector<std::uint32_t> sphere_index_, quad_index_, triangle_index_, disk_index_;  // scene
  // indices (the world's objects), or indices in their group's order (a group's: spheres, quads,
  // triangles, disks); exact ties go to the later of (instance, index), the world's objects
  // first.

  // An instance as the search reads it: the way into its group's space, and its tree's root.
  struct leaf_instance {
    instance_frame frame;  // the placement's inverse and normal matrix
    std::uint32_t root;    // the group's root among wide_'s nodes
  };
  std::vector<leaf_instance> instances_;
  bool with_uv_ = false;  // spheres' hits carry texture coordinates (the scene has images)
};

}  // namespace rtvk
