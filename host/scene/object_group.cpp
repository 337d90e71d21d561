#include "object_group.h"

#include <stdexcept>
#include <utility>

#include "scene.h"

namespace rtvk {

std::optional<sphere> placed(const sphere& sp, const transform& t) {
  if (t.is_identity()) return sp;
  const std::optional<double> scale = t.uniform_scale();
  if (!scale) return std::nullopt;
  sphere out = sp;
  out.center = t.apply_point(sp.center);
  if (sp.center1) out.center1 = t.apply_point(*sp.center1);
  out.radius = sp.radius * *scale;
  return out;
}

quad placed(const quad& q, const transform& t) {
  quad out = q;
  out.Q = t.apply_point(q.Q);
  out.u = t.apply_vector(q.u);
  out.v = t.apply_vector(q.v);
  if (t.determinant() < 0) std::swap(out.u, out.v);  // mirrored: the front stays where it was
  return out;
}

triangle placed(const triangle& tri, const transform& t) {
  triangle out = tri;
  for (std::size_t k = 0; k < 3; ++k) out.p[k] = t.apply_point(tri.p[k]);
  if (t.determinant() < 0) std::swap(out.p[1], out.p[2]);  // the winding put back
  return out;
}

std::optional<disk> placed(const disk& d, const transform& t) {
  if (t.is_identity()) return d;
  const std::optional<double> scale = t.uniform_scale();
  if (!scale) return std::nullopt;
  disk out = d;
  out.center = t.apply_point(d.center);
  out.normal = t.apply_normal(d.normal);
  out.radius = d.radius * *scale;
  return out;
}

triangle_shading placed(const triangle_shading& sh, const transform& t) {
  triangle_shading out = sh;
  if (sh.has_normals() && !t.is_identity())
    for (std::size_t k = 0; k < 3; ++k) out.normal[k] = t.apply_normal(sh.normal[k]);
  const bool mirrored = t.determinant() < 0;
  // Tangents are directions in the surface: carried by the linear part (not the normals' inverse
  // transpose), and a mirror flips their handedness with the frame (as mesh_builder.h places a
  // file's).
  if (sh.has_tangent && !t.is_identity())
    for (glm::vec4& tangent : out.tangent) {
      const vec3 d = glm::normalize(t.apply_vector(vec3(tangent)));
      tangent = glm::vec4(glm::vec3(d), mirrored ? -tangent.w : tangent.w);
    }
  if (mirrored) {  // as the triangle's vertices
    std::swap(out.tangent[1], out.tangent[2]);
    std::swap(out.normal[1], out.normal[2]);
    std::swap(out.uv[1], out.uv[2]);
    std::swap(out.uv1[1], out.uv1[2]);
    std::swap(out.color[1], out.color[2]);
  }
  return out;
}

std::optional<std::string> place_group(scene& s, const object_group& g, const transform& t) {
  std::vector<sphere> spheres;
  for (const sphere& sp : g.spheres) {
    const std::optional<sphere> p = placed(sp, t);
    if (!p)
      return "the group has a sphere, which a copy cannot stretch (only an instance can: an "
             "ellipsoid)";
    spheres.push_back(*p);
  }
  std::vector<disk> disks;
  for (const disk& d : g.disks) {
    const std::optional<disk> p = placed(d, t);
    if (!p)
      return "the group has a disk, which a copy cannot stretch (only an instance can: an "
             "ellipse)";
    disks.push_back(*p);
  }
  s.spheres.insert(s.spheres.end(), spheres.begin(), spheres.end());
  s.disks.insert(s.disks.end(), disks.begin(), disks.end());
  for (const quad& q : g.quads) s.quads.push_back(placed(q, t));
  for (triangle tri : g.triangles) {
    if (tri.shading >= 0) {
      const triangle_shading sh = placed(g.shading[std::size_t(tri.shading)], t);
      tri.shading = std::int32_t(s.shading.size());
      s.shading.push_back(sh);
    }
    const std::int32_t shading = tri.shading;
    tri = placed(tri, t);
    tri.shading = shading;
    s.triangles.push_back(tri);
  }
  return std::nullopt;
}

scene flatten_instances(const scene& s) {
  scene out = s;
  out.groups.clear();
  out.instances.clear();
  for (const instance& i : s.instances)
    if (const auto why = place_group(out, s.groups[i.group], i.placement))
      throw std::invalid_argument(*why);
  return out;
}

}  // namespace rtvk
