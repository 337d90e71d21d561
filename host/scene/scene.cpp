#include "scene.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "errors.h"
#include "format.h"

namespace rtvk {

std::vector<material> scene_materials(const scene& s) {
  std::vector<material> out;
  out.reserve(s.materials.size());
  for (const auto& nm : s.materials) out.push_back(nm.m);
  return out;
}

namespace {

void check_point(const std::string& what, const point3& p) {
  const auto in_range = [](double v) { return std::abs(v) <= max_scene_coordinate; };
  if (!in_range(p.x) || !in_range(p.y) || !in_range(p.z))
    throw usage_error(what + " must be finite and within +-1e18, got " + format_number(p.x) + "," +
                      format_number(p.y) + "," + format_number(p.z));
}

}  // namespace

namespace {

// The objects of the scene, or of one of its groups (`who`: "scene" or "scene: group g").
void check_objects(const std::string& who, const shape_lists& s,
                   const std::function<void(const std::string&, int)>& check_material) {
  for (std::size_t i = 0; i < s.spheres.size(); ++i) {
    const sphere& sp = s.spheres[i];
    const std::string where = who + ": sphere " + std::to_string(i);
    const auto in_range = [](double v) { return std::abs(v) <= max_scene_coordinate; };
    if (!in_range(sp.center.x) || !in_range(sp.center.y) || !in_range(sp.center.z))
      throw usage_error(where + ": center must be finite and within +-1e18, got " +
                        format_number(sp.center.x) + "," + format_number(sp.center.y) + "," +
                        format_number(sp.center.z));
    const point3 c1 = sp.center_at(1);
    if (!in_range(c1.x) || !in_range(c1.y) || !in_range(c1.z))
      throw usage_error(where + ": center1 must be finite and within +-1e18, got " +
                        format_number(c1.x) + "," + format_number(c1.y) + "," +
                        format_number(c1.z));
    if (!(sp.radius > 0) || !in_range(sp.radius))
      throw usage_error(where + ": radius must be > 0 and at most 1e18, got " +
                        format_number(sp.radius));
    check_material(where, sp.material);
  }
  for (std::size_t i = 0; i < s.quads.size(); ++i) {
    const quad& q = s.quads[i];
    const std::string where = who + ": quad " + std::to_string(i);
    check_point(where + ": Q", q.Q);
    check_point(where + ": Q + u + v", q.Q + q.u + q.v);
    check_point(where + ": u", q.u);
    check_point(where + ": v", q.v);
    if (!spans_area(q.u, q.v))
      throw usage_error(where + ": u and v are parallel (or zero): the quad has no area");
    check_material(where, q.material);
  }
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    const triangle& t = s.triangles[i];
    const std::string where = who + ": triangle " + std::to_string(i);
    for (int k = 0; k < 3; ++k) check_point(where + ": vertex " + std::to_string(k), t.p[k]);
    if (!has_area(t.p)) throw usage_error(where + ": its vertices are collinear: no area");
    check_material(where, t.material);
    if (t.shading >= 0 && std::size_t(t.shading) >= s.shading.size())
      throw usage_error(where + ": shading index " + std::to_string(t.shading) + " does not exist");
  }
  for (std::size_t i = 0; i < s.disks.size(); ++i) {
    const disk& d = s.disks[i];
    const std::string where = who + ": disk " + std::to_string(i);
    check_point(where + ": center", d.center);
    check_point(where + ": normal", d.normal);
    if (!has_direction(d.normal))
      throw usage_error(where + ": normal is zero: the disk has no plane");
    if (!(d.radius > 0) || !(d.radius <= max_scene_coordinate))
      throw usage_error(where + ": radius must be > 0 and at most 1e18, got " +
                        format_number(d.radius));
    check_material(where, d.material);
  }
}

// The corners of the box around a group's objects: each shape's own box.
std::vector<point3> group_corners(const object_group& g) {
  point3 lo(INFINITY), hi(-INFINITY);
  for_each_kind(g, [&](const auto& list) {
    for (const auto& shape : list)
      for (const point3& p : shape.bounds()) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
  });
  std::vector<point3> out;
  for (int c = 0; c < 8; ++c)
    out.push_back(point3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z));
  return out;
}

}  // namespace

namespace {

// Textures that exist and can be drawn; media with an isotropic material, a density and a
// boundary the kernels can use.
void check_appearance(const scene& s) {
  for (const named_material& m : s.materials) {
    const int t = m.m.texture;
    if (t != -1 && (t < 0 || std::size_t(t) >= s.textures.size()))
      throw usage_error(s.name + ": material " + m.name + ": texture index " + std::to_string(t) +
                        " does not exist");
  }
  std::set<const texel_image*> images;
  std::uint64_t texels = 0;
  for (std::size_t i = 0; i < s.textures.size(); ++i) {
    const texture& t = s.textures[i];
    const std::string who = s.name + ": texture " + std::to_string(i);
    if (!(t.scale >= 1e-6 && t.scale <= 1e6))
      throw usage_error(who + ": scale must be in [1e-06, 1e+06], got " + format_number(t.scale));
    if (t.image && images.insert(t.image.get()).second) texels += t.image->texels.size();
    if (t.type == texture_type::image &&
        (!t.image || t.image->width <= 0 || t.image->height <= 0 ||
         t.image->texels.size() != std::size_t(t.image->width) * std::size_t(t.image->height)))
      throw usage_error(who + ": an image texture without its texels");
  }
  if (texels > max_scene_texels)
    throw usage_error(s.name + ": the scene's images hold " + std::to_string(texels) +
                      " texels, past the limit of " + std::to_string(max_scene_texels));
  if (s.media.size() > max_scene_media)
    throw usage_error(s.name + ": " + std::to_string(s.media.size()) + " media are more than " +
                      std::to_string(max_scene_media));
  for (std::size_t i = 0; i < s.media.size(); ++i) {
    const medium& m = s.media[i];
    const std::string who = s.name + ": medium " + std::to_string(i);
    if (m.material < 0 || std::size_t(m.material) >= s.materials.size() ||
        s.materials[std::size_t(m.material)].m.type != material_type::isotropic)
      throw usage_error(who + ": its material must be an isotropic one of the scene's");
    if (!(m.density > 0) || !std::isfinite(m.density))
      throw usage_error(who + ": density must be finite and > 0, got " + format_number(m.density));
    if (m.shape == boundary_shape::sphere) {
      check_point(who + ": center", m.center);
      if (!(m.radius > 0) || !(m.radius <= max_scene_coordinate))
        throw usage_error(who + ": radius must be > 0 and within 1e18, got " +
                          format_number(m.radius));
    } else {
      check_point(who + ": corner", m.lo);
      check_point(who + ": corner", m.hi);
      if (!(m.lo.x < m.hi.x && m.lo.y < m.hi.y && m.lo.z < m.hi.z))
        throw usage_error(who + ": its box is flat or inside out");
      if (const auto why = degenerate(m.placement)) throw usage_error(who + ": " + *why);
    }
  }
}

}  // namespace

void check_scene(const scene& s) {
  const auto check_material = [&](const std::string& where, int material) {
    if (material < 0 || std::size_t(material) >= s.materials.size())
      throw usage_error(where + ": material index " + std::to_string(material) + " does not exist");
  };
  if (s.cameras.empty()) throw usage_error(s.name + ": the scene has no camera");
  if (object_count(s) > max_scene_objects)
    throw usage_error(s.name + ": " + std::to_string(object_count(s)) + " objects are more than " +
                      std::to_string(max_scene_objects) + " (a BVH leaf reference's 28 bits)");
  for (std::size_t i = 0; i < s.cameras.size(); ++i) {
    const named_camera& c = s.cameras[i];
    if (!valid_camera_name(c.name))
      throw usage_error(s.name + ": camera " + std::to_string(i) + ": name \"" + c.name +
                        "\" is not a valid camera name");
    for (std::size_t k = 0; k < i; ++k)
      if (s.cameras[k].name == c.name)
        throw usage_error(s.name + ": two cameras are named \"" + c.name + "\"");
    try {
      check_camera_path(c.path);
    } catch (const std::invalid_argument& e) {
      throw usage_error(s.name + ": camera " + c.name + ": " + e.what());
    }
  }
  check_objects(s.name, s, check_material);
  for (const object_group& g : s.groups) {
    const std::string who = s.name + ": group " + g.name;
    if (empty(g)) throw usage_error(who + ": the group has no object");
    check_objects(who, g, check_material);
    for (std::size_t i = 0; i < g.spheres.size(); ++i)
      if (g.spheres[i].center1)
        throw usage_error(who + ": sphere " + std::to_string(i) + " moves (a group's cannot)");
  }
  for (std::size_t i = 0; i < s.instances.size(); ++i) {
    const instance& in = s.instances[i];
    const std::string where = s.name + ": instance " + std::to_string(i);
    if (in.group >= s.groups.size())
      throw usage_error(where + ": group index " + std::to_string(in.group) + " does not exist");
    if (const auto why = degenerate(in.placement)) throw usage_error(where + ": " + *why);
    for (const point3& c : group_corners(s.groups[in.group]))
      check_point(where + ": its group's bounds, placed,", in.placement.apply_point(c));
  }
  check_appearance(s);
}

void add_box(scene& s, const point3& a, const point3& b, int material, const transform& t) {
  const point3 lo = glm::min(a, b), hi = glm::max(a, b);
  const vec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
  const bool mirrored = t.determinant() < 0;  // then u and v trade places: the front stays out
  s.compounds.push_back({false, std::uint32_t(s.quads.size()), 6});
  const auto side = [&](const point3& Q, const vec3& u, const vec3& v) {
    const vec3 tu = t.apply_vector(u), tv = t.apply_vector(v);
    s.quads.push_back({t.apply_point(Q), mirrored ? tv : tu, mirrored ? tu : tv, material});
  };
  side({lo.x, lo.y, hi.z}, dx, dy);   // front
  side({hi.x, lo.y, hi.z}, -dz, dy);  // right
  side({hi.x, lo.y, lo.z}, -dx, dy);  // back
  side({lo.x, lo.y, lo.z}, dz, dy);   // left
  side({lo.x, hi.y, hi.z}, dx, -dz);  // top
  side({lo.x, lo.y, lo.z}, dx, dz);   // bottom
}

bool scene_reads_uv(const scene& s) {
  for (const texture& t : s.textures)
    if (t.type == texture_type::image) return true;
  return false;
}

bool scene_moves(const scene& s) {
  return std::any_of(s.spheres.begin(), s.spheres.end(),
                     [](const sphere& sp) { return sp.velocity() != vec3(0); });
}

time_span shutter_span(const scene& s, double time) {
  const camera_pose first = main_camera(s).at(time);
  time_span span{time + first.shutter_open, time + first.shutter_close + std::abs(first.readout)};
  for (const named_camera& c : s.cameras) {
    const camera_pose p = c.path.at(time);
    span.lo = std::min(span.lo, time + p.shutter_open);
    span.hi = std::max(span.hi, time + p.shutter_close + std::abs(p.readout));  // the last row's
  }
  return span;
}

void check_motion_span(time_span motion, bool moves, const camera& cam) {
  if (moves && !(motion.lo <= cam.time_open() && cam.time_close() <= motion.hi))
    throw std::invalid_argument("the shutter's instants [" + format_number(cam.time_open()) + ", " +
                                format_number(cam.time_close()) +
                                "] s are outside the span the moving spheres are bounded over [" +
                                format_number(motion.lo) + ", " + format_number(motion.hi) + "]");
}

}  // namespace rtvk
