// A glTF file's KHR_lights_punctual lights as the scene's punctual lights: each node of the
// default scene whose extensions name a light, placed by the node's world transform and the
// placement the loader applies (mesh_placement). A light shines down its node's local -Z; a spot's
// cones are radians in glTF and degrees in rtvk. `range` is read and not applied: rtvk's lights
// are unbounded, falling off as the inverse square (docs/lighting.md says why).
#include <cmath>
#include <numbers>

#include "errors.h"
#include "format.h"
#include "gltf_ext.h"
#include "gltf_reader.h"

namespace rtvk {
namespace {

constexpr double degrees = 180 / std::numbers::pi;

class light_collector {
 public:
  light_collector(scene& s, const tinygltf::Model& m, std::string name)
      : s_(s), m_(m), name_(std::move(name)) {}

  void walk(int index, const transform& parent, int depth) {
    // The mesh walker has checked the tree (indices, depth, no node twice) already.
    if (index < 0 || std::size_t(index) >= m_.nodes.size() || depth > 64) return;
    const tinygltf::Node& n = m_.nodes[std::size_t(index)];
    const transform world = compose(parent, node_transform(n));
    const auto ext = n.extensions.find("KHR_lights_punctual");
    if (ext != n.extensions.end()) add(ext->second, index, world);
    for (const int c : n.children) walk(c, world, depth + 1);
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw usage_error(name_ + ": " + where + ": " + what);
  }

  void add(const tinygltf::Value& ext, int node, const transform& world) {
    const std::string where = "node " + std::to_string(node) + " KHR_lights_punctual";
    const tinygltf::Value& index = ext.Get("light");
    if (!index.IsNumber()) fail(where, "has no light index");
    const int k = index.GetNumberAsInt();
    if (k < 0 || std::size_t(k) >= m_.lights.size())
      fail(where, "light " + std::to_string(k) + " does not exist");
    if (s_.punctual_lights.size() >= max_punctual_lights)
      fail(where, "more than " + std::to_string(max_punctual_lights) + " lights");
    punctual_light l = read(m_.lights[std::size_t(k)], where + ": light " + std::to_string(k));
    if (l.name.empty()) l.name = m_.nodes[std::size_t(node)].name;
    l.position = world.apply_point(point3(0));
    const vec3 d = world.apply_vector(vec3(0, 0, -1));
    if (!(glm::dot(d, d) >= 1e-24 && std::isfinite(glm::dot(d, d))) ||
        !std::isfinite(glm::dot(l.position, l.position)))
      fail(where, "its node's transform cannot place a light (scale 0 or not finite)");
    l.direction = glm::normalize(d);
    s_.punctual_lights.push_back(l);
  }

  // The light's own fields, checked: a kind, a color in [0, 1], an intensity >= 0, a spot's
  // cones with 0 <= inner < outer <= pi / 2 (the extension's rule).
  punctual_light read(const tinygltf::Light& g, const std::string& where) const {
    punctual_light l;
    l.name = g.name;
    if (g.type == "point")
      l.kind = punctual_kind::point;
    else if (g.type == "spot")
      l.kind = punctual_kind::spot;
    else if (g.type == "directional")
      l.kind = punctual_kind::directional;
    else
      fail(where, "type \"" + g.type + "\" is not point, spot or directional");
    if (!g.color.empty()) {
      if (g.color.size() != 3)
        fail(where, "color has " + std::to_string(g.color.size()) + " values, not 3");
      for (std::size_t c = 0; c < 3; ++c)
        if (!(g.color[c] >= 0 && g.color[c] <= 1))
          fail(where, "color " + format_number(g.color[c]) + " is not in [0, 1]");
      l.tint = color(g.color[0], g.color[1], g.color[2]);
    }
    if (!(g.intensity >= 0 && std::isfinite(g.intensity)))
      fail(where, "intensity " + format_number(g.intensity) + " is not a finite number >= 0");
    l.intensity = g.intensity;
    if (l.kind == punctual_kind::spot) {
      const double inner = g.spot.innerConeAngle, outer = g.spot.outerConeAngle;
      if (!(inner >= 0 && inner < outer && outer <= std::numbers::pi / 2))
        fail(where, "spot cones " + format_number(inner) + " and " + format_number(outer) +
                        " are not 0 <= inner < outer <= pi / 2");
      l.inner_cone = inner * degrees;
      l.outer_cone = outer * degrees;
    }
    return l;
  }

  scene& s_;
  const tinygltf::Model& m_;
  std::string name_;  // the file, as messages name it
};

}  // namespace

void add_gltf_lights(scene& s, const tinygltf::Model& m, const std::string& name,
                     const transform& placement) {
  light_collector collect(s, m, name);
  const int scene = m.defaultScene >= 0 ? m.defaultScene : 0;
  if (std::size_t(scene) < m.scenes.size()) {
    for (const int n : m.scenes[std::size_t(scene)].nodes) collect.walk(n, placement, 0);
    return;
  }
  std::vector<bool> child(m.nodes.size());  // no scenes: every node that is nobody's child
  for (const tinygltf::Node& n : m.nodes)
    for (const int c : n.children)
      if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
  for (std::size_t i = 0; i < child.size(); ++i)
    if (!child[i]) collect.walk(int(i), placement, 0);
}

}  // namespace rtvk
