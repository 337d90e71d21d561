// The fast world's searches and the winner's record, as world.glsl makes it (record_object,
// record_winner): the same kernels on the same float arrays.
#include "fast_world.h"

namespace rtvk::fast {

bool world::hit(const ray& r, real t_min, real t_max, hit_record& rec) const {
  packet_bvh::found f;
  const bool own = packets->hit(r, t_min, t_max, f);
  return finish(r, t_min, t_max, own, f, rec);
}

// After packet_bvh's search (`own`: it found f): Embree's triangles and instances, nearer than
// that, and the winner's record.
bool world::finish(const ray& r, real t_min, real t_max, bool own, const packet_bvh::found& f,
                   hit_record& rec) const {
  if (embree_world) {
    RTCRayHit h = embree_ray(r, t_min, own ? f.t : t_max);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(trees[0].scene, &context, &h);
    if (h.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
      record(h, r, rec);
      return true;
    }
  }
  if (!own) return false;
  record_own(f, r, rec);
  return true;
}

bool world::blocked(const ray& r, real t_min, real t_max) const {
  if (packets->blocked(r, t_min, t_max)) return true;
  if (!embree_world) return false;
  RTCRay e = embree_ray(r, t_min, t_max).ray;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(trees[0].scene, &context, &e);
  return e.tfar < 0;
}

// A hit packet_bvh found among the world's own objects (packet_bvh's kinds are world::kind's).
static_assert(unsigned(packet_bvh::sphere_kind) == world::sphere_kind &&
              unsigned(packet_bvh::quad_kind) == world::quad_kind &&
              unsigned(packet_bvh::disk_kind) == world::disk_kind);
void world::record_own(const packet_bvh::found& f, const ray& r, hit_record& rec) const {
  RTCHit hit{};
  hit.geomID = f.kind;
  hit.primID = f.index;
  record_in(trees[0], hit, r, f.t, rec);
}

// The winner's record: made in its instance's group space when it was reached through one, then
// carried back.
void world::record(const RTCRayHit& h, const ray& r, hit_record& rec) const {
  const std::uint32_t i = h.hit.instID[0];
  if (i == RTC_INVALID_GEOMETRY_ID) return record_in(trees[0], h.hit, r, h.ray.tfar, rec);
  const ray g = to_group(frames[i], r);
  record_in(trees[instance_tree[i]], h.hit, g, h.ray.tfar, rec);
  carry_back(frames[i], r, h.ray.tfar, rec);
}

void world::record_in(const tree& tr, const RTCHit& hit, const ray& r, real t,
                      hit_record& rec) const {
  const std::uint32_t k = tr.first[hit.geomID] + hit.primID;
  switch (hit.geomID) {
    case sphere_kind: {
      const gpu::gpu_sphere& s = arrays.spheres[k];
      const real3 c =
          moves ? moved_center(s.center, real3(arrays.velocities[k]), r.time) : real3(s.center);
      record_hit(c, s.radius, s.material, r, t, arrays.with_uv, rec);
      return;
    }
    case quad_kind:
      record_quad_hit(quads[k], arrays.quads[k].material, r, t, rec);
      return;
    case disk_kind:
      record_disk_hit(disks[k], arrays.disks[k].material, r, t, rec);
      return;
    default:
      break;
  }
  const gpu::gpu_triangle& tri = arrays.triangles[k];
  // The blend's weights are Embree's barycentrics (u toward b, v toward c): the GPU finds them
  // again with the kernels' own test, which would cost a second triangle test here (the anchor
  // benchmark measured it at a fifth of a search); they differ in the last bits.
  const real3 weights(real(1) - hit.u - hit.v, hit.u, hit.v);
  const std::vector<glm::vec4>& normals = arrays.normals;
  const bool shaded = tri.normals != RTVK_FLAT;
  const std::size_t e = 3u * std::size_t(tri.normals);
  const bool blended = shaded && normals[e].w != 0.0f;
  const bool has_uv = shaded && (uint(normals[e + 1].w) & 1u) != 0u;
  real3 n0(0), n1(0), n2(0);
  if (blended) n0 = real3(normals[e]), n1 = real3(normals[e + 1]), n2 = real3(normals[e + 2]);
  real2 uv0(0), uv1(0), uv2(0);
  if (has_uv) uv0 = arrays.uvs[e], uv1 = arrays.uvs[e + 1], uv2 = arrays.uvs[e + 2];
  const real3 shading = shading_normal(tri.a, tri.b, tri.c, blended, n0, n1, n2, weights);
  const real2 uv = triangle_uv(has_uv, uv0, uv1, uv2, weights);
  record_triangle_hit(tri.a, tri.b, tri.c, shading, uv, tri.material, r, t, rec);
  if (!shaded) return;
  // The vertex extras (scene_buffers.glsl's record_vertex_extras): tangents, colors, a second uv.
  const uint tangents = uint(normals[e].w) >> 1u;
  if (tangents != 0u) {
    const std::size_t t3 = 3u * (tangents - 1u);
    rec.tangent = blend_tangents(arrays.tangents[t3], arrays.tangents[t3 + 1],
                                 arrays.tangents[t3 + 2], weights, rec);
  }
  const uint colors = uint(normals[e + 2].w);
  if (colors != 0u)
    rec.color = blend_colors(normals[3u * colors], normals[3u * colors + 1u],
                             normals[3u * colors + 2u], weights);
  const uint second = uint(normals[e + 1].w) >> 1u;
  if (second != 0u)
    rec.uv1 = triangle_uv(true, arrays.uvs[3u * second], arrays.uvs[3u * second + 1u],
                          arrays.uvs[3u * second + 2u], weights);
}

}  // namespace rtvk::fast
