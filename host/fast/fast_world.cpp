// The fast world's construction: packet_bvh over the world's own spheres, quads and disks, and
// Embree's trees (the world's triangles and instances; each instanced group's every object), the
// shapes Embree lacks given to it as callbacks that run the kernels' tests.
#include "fast_world.h"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <stdexcept>
#include <string>

namespace rtvk::fast {
namespace {

const float infinity = std::numeric_limits<float>::infinity();

// Embree's error, as the message of the exception the caller sees.
void check(RTCDevice device, const char* call) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE)
    throw std::runtime_error(std::string(call) + " failed: Embree error " + std::to_string(int(e)));
}

// A box grown by a little more than float's rounding of its corners, so that no hit the kernels'
// float tests find falls outside it.
void grow(RTCBounds& b) {
  const float m =
      1e-5f * std::max({std::abs(b.lower_x), std::abs(b.lower_y), std::abs(b.lower_z),
                        std::abs(b.upper_x), std::abs(b.upper_y), std::abs(b.upper_z), 1.0f});
  b.lower_x -= m, b.lower_y -= m, b.lower_z -= m;
  b.upper_x += m, b.upper_y += m, b.upper_z += m;
}

void include(RTCBounds& b, real3 p) {
  b.lower_x = std::min(b.lower_x, p.x), b.lower_y = std::min(b.lower_y, p.y);
  b.lower_z = std::min(b.lower_z, p.z);
  b.upper_x = std::max(b.upper_x, p.x), b.upper_y = std::max(b.upper_y, p.y);
  b.upper_z = std::max(b.upper_z, p.z);
}

RTCBounds empty_bounds() {
  return {infinity, infinity, infinity, 0, -infinity, -infinity, -infinity, 0};
}

const world::geometry_data& data_of(void* p) {
  return *static_cast<const world::geometry_data*>(p);
}

// Keeps a hit the kernels found at t: the callbacks' common end.
template <typename Args>
void report(const Args* args, RTCRayHit& h, real t) {
  h.ray.tfar = t;
  h.hit.primID = args->primID;
  h.hit.geomID = args->geomID;
  h.hit.instID[0] = args->context->instID[0];
}

// The shapes the kernels test, each as bounds, intersect and occluded callbacks; `test` is the
// kernel's test of primitive k (its place in the arrays) against r, giving t.
template <typename Test>
void intersect_with(const RTCIntersectFunctionNArguments* args, world::kind kind, Test test) {
  if (!args->valid[0]) return;
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  RTCRayHit& h = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  real t;
  if (test(d, d.t->first[kind] + args->primID, ray_of(h.ray), h.ray.tnear, h.ray.tfar, t))
    report(args, h, t);
}
template <typename Test>
void occluded_with(const RTCOccludedFunctionNArguments* args, world::kind kind, Test test) {
  if (!args->valid[0]) return;
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  RTCRay& r = *reinterpret_cast<RTCRay*>(args->ray);
  real t;
  if (test(d, d.t->first[kind] + args->primID, ray_of(r), r.tnear, r.tfar, t)) r.tfar = -infinity;
}

bool test_sphere(const world::geometry_data& d, std::uint32_t k, const ray& r, real t_min,
                 real t_max, real& t) {
  const gpu::gpu_sphere& s = d.w->arrays.spheres[k];
  const real3 c = d.w->moves ? moved_center(s.center, real3(d.w->arrays.velocities[k]), r.time)
                             : real3(s.center);
  return hit_sphere(c, s.radius, r, t_min, t_max, t);
}
bool test_quad(const world::geometry_data& d, std::uint32_t k, const ray& r, real t_min, real t_max,
               real& t) {
  real2 uv;
  return hit_quad(d.w->quads[k], r, t_min, t_max, t, uv);
}
bool test_disk(const world::geometry_data& d, std::uint32_t k, const ray& r, real t_min, real t_max,
               real& t) {
  return hit_disk(d.w->disks[k], r, t_min, t_max, t);
}

void sphere_bounds(const RTCBoundsFunctionArguments* args) {
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  const std::uint32_t k = d.t->first[world::sphere_kind] + args->primID;
  const gpu::gpu_sphere& s = d.w->arrays.spheres[k];
  RTCBounds b = empty_bounds();
  const real3 r(s.radius);
  include(b, s.center - r);
  include(b, s.center + r);
  if (d.w->moves) {  // linear motion: the boxes at the span's ends hold every one between
    const real3 v(d.w->arrays.velocities[k]);
    for (const float time : {d.w->motion_begin, d.w->motion_end}) {
      include(b, moved_center(s.center, v, time) - r);
      include(b, moved_center(s.center, v, time) + r);
    }
  }
  grow(b);
  *args->bounds_o = b;
}
void quad_bounds(const RTCBoundsFunctionArguments* args) {
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  const quad_geometry& q = d.w->quads[d.t->first[world::quad_kind] + args->primID];
  RTCBounds b = empty_bounds();
  for (const real3 p : {q.Q, q.Q + q.u, q.Q + q.v, q.Q + q.u + q.v}) include(b, p);
  grow(b);
  *args->bounds_o = b;
}
void disk_bounds(const RTCBoundsFunctionArguments* args) {
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  const disk_geometry& g = d.w->disks[d.t->first[world::disk_kind] + args->primID];
  RTCBounds b = empty_bounds();
  include(b, g.center - real3(g.radius));
  include(b, g.center + real3(g.radius));
  grow(b);
  *args->bounds_o = b;
}

// An instance: the ray carried into its group's space (the kernels' to_group, the same t), and
// the group's tree searched there; a hit keeps the instance's index in instID[0].
void instance_intersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  RTCRayHit& h = *reinterpret_cast<RTCRayHit*>(args->rayhit);
  const std::uint32_t i = d.t->first[world::instance_kind] + args->primID;
  RTCRayHit g = embree_ray(to_group(d.w->frames[i], ray_of(h.ray)), h.ray.tnear, h.ray.tfar);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(d.w->trees[d.w->instance_tree[i]].scene, &context, &g);
  if (g.hit.geomID == RTC_INVALID_GEOMETRY_ID) return;
  h.ray.tfar = g.ray.tfar;
  h.hit = g.hit;
  h.hit.instID[0] = i;
}
void instance_occluded(const RTCOccludedFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  RTCRay& r = *reinterpret_cast<RTCRay*>(args->ray);
  const std::uint32_t i = d.t->first[world::instance_kind] + args->primID;
  RTCRay g = embree_ray(to_group(d.w->frames[i], ray_of(r)), r.tnear, r.tfar).ray;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(d.w->trees[d.w->instance_tree[i]].scene, &context, &g);
  if (g.tfar < 0) r.tfar = -infinity;
}

// An instance's box: its group tree's, its corners carried into the world by the placement
// (the inverse of to_group, formed in double), grown as every box here.
void instance_bounds(const RTCBoundsFunctionArguments* args) {
  const world::geometry_data& d = data_of(args->geometryUserPtr);
  const std::uint32_t i = d.t->first[world::instance_kind] + args->primID;
  RTCBounds group;
  rtcGetSceneBounds(d.w->trees[d.w->instance_tree[i]].scene, &group);
  const instance_frame& f = d.w->frames[i];
  const glm::dmat3 to_group = glm::transpose(
      glm::dmat3(glm::dvec3(f.to_group_x), glm::dvec3(f.to_group_y), glm::dvec3(f.to_group_z)));
  const glm::dmat3 placement = glm::inverse(to_group);
  RTCBounds b = empty_bounds();
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? group.upper_x : group.lower_x,
                       (c & 2) ? group.upper_y : group.lower_y,
                       (c & 4) ? group.upper_z : group.lower_z);
    include(b, real3(placement * (p - glm::dvec3(f.to_group_offset))));
  }
  grow(b);
  *args->bounds_o = b;
}

instance_frame frame_of(const gpu::gpu_instance& g) {
  instance_frame f;
  f.to_group_x = real3(g.to_group_x), f.to_group_y = real3(g.to_group_y);
  f.to_group_z = real3(g.to_group_z);
  f.to_group_offset = real3(g.to_group_x.w, g.to_group_y.w, g.to_group_z.w);
  f.normal_x = real3(g.normal_x), f.normal_y = real3(g.normal_y), f.normal_z = real3(g.normal_z);
  f.stretch = g.normal_x.w;
  return f;
}

}  // namespace

RTCRayHit embree_ray(const ray& r, real t_min, real t_max) {
  RTCRayHit h;  // every field Embree reads is set here
  h.ray.org_x = r.origin.x, h.ray.org_y = r.origin.y, h.ray.org_z = r.origin.z;
  h.ray.dir_x = r.direction.x, h.ray.dir_y = r.direction.y, h.ray.dir_z = r.direction.z;
  h.ray.tnear = t_min;
  h.ray.tfar = t_max;
  h.ray.time = r.time;
  h.ray.mask = ~0u;
  h.ray.id = 0;
  h.ray.flags = 0;
  h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return h;
}

world::world(const gpu::scene_arrays& a, float motion_begin_, float motion_end_)
    : arrays(a),
      moves(!a.velocities.empty()),
      motion_begin(motion_begin_),
      motion_end(motion_end_),
      device_(rtcNewDevice(nullptr)) {
  if (!device_)
    throw std::runtime_error("rtcNewDevice failed: Embree error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))));
  for (const gpu::gpu_quad& q : a.quads) {
    quad_geometry g;
    g.Q = q.Q, g.u = q.u, g.v = q.v, g.normal = q.normal, g.w = q.w, g.D = q.D;
    quads.push_back(g);
  }
  for (const gpu::gpu_disk& q : a.disks) {
    disk_geometry g;
    g.center = q.center, g.normal = q.normal, g.u = q.u, g.v = q.v, g.radius = q.radius, g.D = q.D;
    disks.push_back(g);
  }
  any_triangles = !a.triangles.empty();
  // The world's own objects lead each array; each group's follow, a run per group, which every
  // instance of the group names (gpu_instance's firsts and counts). One tree per distinct run.
  trees.push_back({});
  trees[0].count = {a.own[0], a.own[1], a.own[3], a.own[2], std::uint32_t(a.instances.size())};
  for (const gpu::gpu_instance& g : a.instances) {
    frames.push_back(frame_of(g));
    const tree t{nullptr,
                 {g.sphere_first, g.quad_first, g.disk_first, g.triangle_first, 0},
                 {g.sphere_count, g.quad_count, g.disk_count, g.triangle_count, 0}};
    std::uint32_t found = 1;
    while (found < trees.size() && (trees[found].first != t.first || trees[found].count != t.count))
      ++found;
    if (found == trees.size()) trees.push_back(t);
    instance_tree.push_back(found);
  }
  // The world's own spheres, quads and disks: packet_bvh's; Embree's world tree keeps the rest.
  trees[0].packed = true;
  packets =
      std::make_unique<packet_bvh>(a, trees[0].count[sphere_kind], quads, trees[0].count[quad_kind],
                                   disks, trees[0].count[disk_kind], motion_begin, motion_end);
  embree_world = trees[0].count[triangle_kind] > 0 || trees[0].count[instance_kind] > 0;
  data_.reserve(trees.size() * kinds);
  // Groups first: an instance's bounds are its group tree's, carried into the world.
  for (std::size_t k = trees.size(); k-- > 0;) build_tree(trees[k]);
}

// Whether Embree's own primitives stand for objects of kind k: spheres that stand still, quads
// and triangles. Moving spheres, disks and instances run the kernels' tests in callbacks.
bool world::native(unsigned k) const {
  return k == quad_kind || k == triangle_kind;
}

void world::attach(tree& t, RTCGeometry g, unsigned id) {
  rtcCommitGeometry(g);
  rtcAttachGeometryByID(t.scene, g, id);
  rtcReleaseGeometry(g);
  check(device_, "rtcCommitGeometry");
}

// The tree's Embree scene: a user geometry per kind the kernels test, Embree's own triangles
// (the array's vertices read in place: a, b and c of each gpu_triangle, 16 bytes apart).
void world::build_tree(tree& t) {
  t.scene = rtcNewScene(device_);
  check(device_, "rtcNewScene");
  rtcSetSceneBuildQuality(t.scene, RTC_BUILD_QUALITY_HIGH);
  struct user_kind {
    kind k;
    RTCBoundsFunction bounds;
    RTCIntersectFunctionN intersect;
    RTCOccludedFunctionN occluded;
  };
  const user_kind users[] = {
      {sphere_kind, sphere_bounds,
       [](const RTCIntersectFunctionNArguments* a) { intersect_with(a, sphere_kind, test_sphere); },
       [](const RTCOccludedFunctionNArguments* a) { occluded_with(a, sphere_kind, test_sphere); }},
      {quad_kind, quad_bounds,
       [](const RTCIntersectFunctionNArguments* a) { intersect_with(a, quad_kind, test_quad); },
       [](const RTCOccludedFunctionNArguments* a) { occluded_with(a, quad_kind, test_quad); }},
      {disk_kind, disk_bounds,
       [](const RTCIntersectFunctionNArguments* a) { intersect_with(a, disk_kind, test_disk); },
       [](const RTCOccludedFunctionNArguments* a) { occluded_with(a, disk_kind, test_disk); }},
      {instance_kind, instance_bounds, instance_intersect, instance_occluded}};
  const auto in_embree = [&](unsigned k) {
    return t.count[k] > 0 && !(t.packed && k != triangle_kind && k != instance_kind);
  };
  for (const user_kind& u : users) {
    if (!in_embree(u.k) || native(u.k)) continue;
    data_.push_back({this, &t});
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    check(device_, "rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(g, t.count[u.k]);
    rtcSetGeometryUserData(g, &data_.back());
    rtcSetGeometryBoundsFunction(g, u.bounds, nullptr);
    rtcSetGeometryIntersectFunction(g, u.intersect);
    rtcSetGeometryOccludedFunction(g, u.occluded);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(t.scene, g, u.k);
    rtcReleaseGeometry(g);
    check(device_, "rtcCommitGeometry");
  }
  if (native(sphere_kind) && in_embree(sphere_kind)) {
    // Spheres that stand still: Embree's own, tested several at once. Each gpu_sphere begins
    // with its center and radius, the float4 Embree reads, 32 bytes apart.
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    check(device_, "rtcNewGeometry");
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                               &arrays.spheres[t.first[sphere_kind]], 0, sizeof(gpu::gpu_sphere),
                               t.count[sphere_kind]);
    attach(t, g, sphere_kind);
  }
  if (native(quad_kind) && in_embree(quad_kind)) {
    // Quads: Embree's, each of its four corners (a parallelogram is planar, so Embree's two
    // triangles cover it exactly).
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_QUAD);
    check(device_, "rtcNewGeometry");
    const std::uint32_t n = t.count[quad_kind];
    auto* corner = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n));
    auto* index = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(std::uint32_t), n));
    check(device_, "rtcSetNewGeometryBuffer");
    for (std::uint32_t k = 0; k < n; ++k) {
      const quad_geometry& q = quads[t.first[quad_kind] + k];
      const real3 p[4] = {q.Q, q.Q + q.u, q.Q + q.u + q.v, q.Q + q.v};
      for (int c = 0; c < 4; ++c) {
        for (int x = 0; x < 3; ++x) corner[12 * k + 3 * c + x] = p[c][x];
        index[4 * k + c] = 4 * k + c;
      }
    }
    attach(t, g, quad_kind);
  }
  if (t.count[triangle_kind] > 0) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    check(device_, "rtcNewGeometry");
    const std::uint32_t n = t.count[triangle_kind];
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               &arrays.triangles[t.first[triangle_kind]], 0, 16, 3 * n);
    auto* index = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), n));
    check(device_, "rtcSetNewGeometryBuffer");
    for (std::uint32_t k = 0; k < 3 * n; ++k) index[k] = k;
    attach(t, g, triangle_kind);
  }
  rtcCommitScene(t.scene);
  check(device_, "rtcCommitScene");
}

world::~world() {
  for (tree& t : trees)
    if (t.scene) rtcReleaseScene(t.scene);
  if (device_) rtcReleaseDevice(device_);
}

}  // namespace rtvk::fast
