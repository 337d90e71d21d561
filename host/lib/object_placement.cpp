#include "object_placement.h"

#include <optional>

#include "object_group.h"
#include "object_ids.h"

namespace rtvk {
namespace {

// The box around shapes [first, first + count) of `list` (each shape's own box).
template <class List>
void bound(const List& list, std::size_t first, std::size_t count, object_original& o) {
  o.lo = point3(INFINITY);
  o.hi = point3(-INFINITY);
  for (std::size_t k = first; k < first + count; ++k)
    for (const point3& p : list[k].bounds()) {
      o.lo = glm::min(o.lo, p);
      o.hi = glm::max(o.hi, p);
    }
}

// The box around a group's objects.
object_original group_box(const object_group& g) {
  object_original box;
  box.lo = point3(INFINITY);
  box.hi = point3(-INFINITY);
  for_each_kind(g, [&](const auto& list) {
    object_original one;
    if (list.empty()) return;
    bound(list, 0, list.size(), one);
    box.lo = glm::min(box.lo, one.lo);
    box.hi = glm::max(box.hi, one.hi);
  });
  return box;
}

// The box around an instance: its group's box's corners, placed.
void bound_instance(const object_original& group, const transform& placement, object_original& o) {
  o.lo = point3(INFINITY);
  o.hi = point3(-INFINITY);
  for (int c = 0; c < 8; ++c) {
    const point3 corner(c & 1 ? group.hi.x : group.lo.x, c & 2 ? group.hi.y : group.lo.y,
                        c & 4 ? group.hi.z : group.lo.z);
    o.lo = glm::min(o.lo, placement.apply_point(corner));
    o.hi = glm::max(o.hi, placement.apply_point(corner));
  }
}

// The kinds of the scene's own objects in scene-index order (shape_lists' for_each_kind).
enum class list_kind { spheres, quads, triangles, disks };

// Which list scene index `k` falls in, and its place there.
list_kind kind_at(const scene& s, std::size_t& k) {
  if (k < s.spheres.size()) return list_kind::spheres;
  k -= s.spheres.size();
  if (k < s.quads.size()) return list_kind::quads;
  k -= s.quads.size();
  if (k < s.triangles.size()) return list_kind::triangles;
  k -= s.triangles.size();
  return list_kind::disks;
}

const char* kind_name(list_kind k, std::size_t count) {
  switch (k) {
    case list_kind::spheres:
      return "sphere";
    case list_kind::quads:
      return count > 1 ? "box" : "quad";
    case list_kind::triangles:
      return count > 1 ? "mesh" : "triangle";
    case list_kind::disks:
      return "disk";
  }
  return "";
}

// Calls f(list, kept) with the scene's list of `kind` and kept's list of the same kind.
template <class F>
void with_lists(const scene& s, list_kind kind, shape_lists& kept, F&& f) {
  switch (kind) {
    case list_kind::spheres:
      return f(s.spheres, kept.spheres);
    case list_kind::quads:
      return f(s.quads, kept.quads);
    case list_kind::triangles:
      return f(s.triangles, kept.triangles);
    case list_kind::disks:
      return f(s.disks, kept.disks);
  }
}

// The scene's own object whose primitives are scene indices [begin, end).
// `shapes`: with copies of its primitives.
object_original own_object(const scene& s, std::uint32_t id, std::size_t begin, std::size_t end,
                           bool shapes) {
  std::size_t first = begin;
  const list_kind kind = kind_at(s, first);
  const std::size_t count = end - begin;
  object_original o;
  o.id = id;
  o.kind = kind_name(kind, count);
  o.first = first;
  o.count = count;
  with_lists(s, kind, o.shapes, [&](const auto& list, auto& copy) {
    bound(list, first, count, o);
    o.material = list[first].material;
    if (shapes)
      copy.assign(list.begin() + std::ptrdiff_t(first),
                  list.begin() + std::ptrdiff_t(first + count));
  });
  for (const triangle& t : o.shapes.triangles)  // their shading, in their order
    if (t.shading >= 0) o.shapes.shading.push_back(s.shading[std::size_t(t.shading)]);
  return o;
}

}  // namespace

namespace {

// Every object, with its primitives where `shapes`, or only `only`'s (0: every one).
std::vector<object_original> objects(const scene& s, bool shapes, std::uint32_t only) {
  const object_ids ids(s);
  std::vector<object_original> out;
  const std::size_t own = shape_count(s);
  for (std::size_t k = 0; k < own;) {
    const std::uint32_t id = ids.of(std::uint32_t(k), 0);
    std::size_t end = k + 1;
    while (end < own && ids.of(std::uint32_t(end), 0) == id) ++end;
    if (only == 0 || id == only) out.push_back(own_object(s, id, k, end, shapes));
    k = end;
  }
  std::vector<std::optional<object_original>> groups(s.groups.size());  // boxes, made once
  for (std::size_t i = 0; i < s.instances.size(); ++i) {
    object_original o;
    o.id = ids.of(0, std::uint32_t(i + 1));
    if (only != 0 && o.id != only) continue;
    o.kind = "instance";
    o.first = i;
    o.count = object_count(s.groups[s.instances[i].group]);
    o.group = s.instances[i].group;
    o.instance_placement = s.instances[i].placement;
    if (!groups[o.group]) groups[o.group] = group_box(s.groups[o.group]);
    bound_instance(*groups[o.group], o.instance_placement, o);
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace

std::vector<object_original> list_objects(const scene& s) {
  return objects(s, false, 0);
}

std::optional<object_original> find_object(const scene& s, std::uint32_t id) {
  if (id == 0) return std::nullopt;
  std::vector<object_original> found = objects(s, true, id);
  if (found.empty()) return std::nullopt;
  return std::move(found.front());
}

std::optional<std::string> place_object(scene& s, const object_original& o, const transform& t) {
  if (o.kind == "instance") {
    s.instances[o.first].placement = compose(t, o.instance_placement);
    return std::nullopt;
  }
  std::vector<sphere> spheres;
  for (const sphere& sp : o.shapes.spheres) {
    const std::optional<sphere> p = placed(sp, t);
    if (!p) return "a sphere can be turned, moved and scaled evenly, not stretched";
    spheres.push_back(*p);
  }
  std::vector<disk> disks;
  for (const disk& d : o.shapes.disks) {
    const std::optional<disk> p = placed(d, t);
    if (!p) return "a disk can be turned, moved and scaled evenly, not stretched";
    disks.push_back(*p);
  }
  for (std::size_t k = 0; k < spheres.size(); ++k) s.spheres[o.first + k] = spheres[k];
  for (std::size_t k = 0; k < disks.size(); ++k) s.disks[o.first + k] = disks[k];
  for (std::size_t k = 0; k < o.shapes.quads.size(); ++k)
    s.quads[o.first + k] = placed(o.shapes.quads[k], t);
  std::size_t shaded = 0;  // the originals' shading, in their triangles' order
  for (std::size_t k = 0; k < o.shapes.triangles.size(); ++k) {
    const triangle& original = o.shapes.triangles[k];
    triangle& now = s.triangles[o.first + k];
    now = placed(original, t);
    now.shading = original.shading;
    if (original.shading >= 0)
      s.shading[std::size_t(original.shading)] = placed(o.shapes.shading[shaded++], t);
  }
  return std::nullopt;
}

}  // namespace rtvk
