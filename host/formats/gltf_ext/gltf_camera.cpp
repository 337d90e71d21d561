// A glTF file's cameras as scene cameras: each node of the default scene with a camera, posed by
// the node's world transform. glTF's camera looks down its local -Z with +Y up and +X to the
// right; its perspective projection has a vertical field of view (yfov, radians) and an
// orthographic one half the view's width and height (xmag, ymag). rtvk's renderers have no near
// or far plane: znear and zfar are read and not used (everything in front of the eye is drawn).
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "camera_path.h"
#include "errors.h"
#include "gltf_ext.h"

namespace rtvk {

transform node_transform(const tinygltf::Node& n) {
  transform t;
  if (n.matrix.size() == 16) {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) t.linear[c][r] = n.matrix[std::size_t(4 * c + r)];
    t.offset = vec3(n.matrix[12], n.matrix[13], n.matrix[14]);
    return t;
  }
  glm::dmat3 scale(1.0), rotation(1.0);
  if (n.scale.size() == 3) scale = glm::dmat3(n.scale[0], 0, 0, 0, n.scale[1], 0, 0, 0, n.scale[2]);
  if (n.rotation.size() == 4)  // x, y, z, w
    rotation =
        glm::mat3_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
  t.linear = rotation * scale;
  if (n.translation.size() == 3)
    t.offset = vec3(n.translation[0], n.translation[1], n.translation[2]);
  return t;
}

namespace {

// A camera name --camera accepts (valid_camera_name): other characters become '_'.
std::string usable_name(const std::string& raw) {
  std::string out;
  for (const char c : raw.substr(0, 56))
    out +=
        std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.' ? c : '_';
  while (!out.empty() && out.front() == '.') out.erase(out.begin());
  return out == "all" ? "all_" : out;
}

class camera_collector {
 public:
  camera_collector(scene& s, const tinygltf::Model& m, std::string name)
      : s_(s), m_(m), name_(std::move(name)) {}

  void walk(int index, const transform& parent, int depth) {
    // mesh_gltf.cpp's walker has checked the tree (indices, depth, no node twice) already.
    if (index < 0 || std::size_t(index) >= m_.nodes.size() || depth > 64) return;
    const tinygltf::Node& n = m_.nodes[std::size_t(index)];
    const transform world = compose(parent, node_transform(n));
    if (n.camera >= 0) add(n, index, world);
    for (const int c : n.children) walk(c, world, depth + 1);
  }

  bool first_sets_aspect = false;  // the first camera added sets s.render.aspect

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw usage_error(name_ + ": " + where + ": " + what);
  }

  void add(const tinygltf::Node& n, int node, const transform& world) {
    const std::string where =
        "node " + std::to_string(node) + " camera " + std::to_string(n.camera);
    if (std::size_t(n.camera) >= m_.cameras.size()) fail(where, "does not exist");
    const tinygltf::Camera& c = m_.cameras[std::size_t(n.camera)];
    camera_pose pose;
    const double reach = orthographic_reach(c, where);  // eye to look-at, scene units
    pose.lookfrom = world.apply_point(point3(0));
    const vec3 ahead = world.apply_vector(vec3(0, 0, -1)), up = world.apply_vector(vec3(0, 1, 0));
    if (!(glm::length(pose.lookfrom) < max_scene_coordinate) ||
        !(glm::length(glm::cross(ahead, up)) > 1e-12) || !std::isfinite(glm::length(ahead)))
      fail(where, "the node's transform does not pose a camera (a view direction and an up)");
    pose.lookat = pose.lookfrom + reach * glm::normalize(ahead);
    pose.vup = up;
    pose.focus_dist = reach;
    double aspect = 0;
    if (c.type == "perspective") {
      const double yfov = c.perspective.yfov;
      if (!(yfov > 0 && yfov < M_PI))
        fail(where, "yfov " + std::to_string(yfov) + " is not in (0, pi)");
      pose.vfov = yfov * 180 / M_PI;
      aspect = c.perspective.aspectRatio;
    } else {
      // The orthographic viewport is the perspective one's on the focus plane (docs/camera.md):
      // 90 degrees at ymag away spans 2 ymag.
      pose.projection = projection::orthographic;
      pose.vfov = 90;
      aspect = c.orthographic.xmag / c.orthographic.ymag;
    }
    if (aspect != 0 && !(aspect >= 1e-3 && aspect <= 1e3))
      fail(where, "aspect ratio " + std::to_string(aspect) + " is not in [0.001, 1000]");
    if (first_sets_aspect && aspect > 0) s_.render.aspect = aspect;
    first_sets_aspect = false;
    s_.cameras.push_back({unique(c.name.empty() ? n.name : c.name, n.camera), {}});
    s_.cameras.back().path.pose = pose;
  }

  // The distance from the eye to the look-at point: 1, or for an orthographic camera ymag, so
  // that the viewport (2 ymag high at 90 degrees) is the glTF one.
  double orthographic_reach(const tinygltf::Camera& c, const std::string& where) const {
    if (c.type == "perspective") return 1;
    if (c.type != "orthographic")
      fail(where, "type \"" + c.type + "\" is not perspective or orthographic");
    const double x = c.orthographic.xmag, y = c.orthographic.ymag;
    if (!(x > 0 && x < 1e18) || !(y > 0 && y < 1e18))
      fail(where, "xmag " + std::to_string(x) + " and ymag " + std::to_string(y) +
                      " are not both in (0, 1e18)");
    return y;
  }

  // The camera's name made usable and unique among the scene's cameras.
  std::string unique(const std::string& raw, int camera) const {
    std::string base = usable_name(raw);
    if (base.empty()) base = "camera" + std::to_string(camera);
    std::string name = base;
    const auto taken = [&](const std::string& x) {
      return std::any_of(s_.cameras.begin(), s_.cameras.end(),
                         [&](const named_camera& n) { return n.name == x; });
    };
    for (int k = 2; taken(name); ++k) name = base + "-" + std::to_string(k);
    return name;
  }

  scene& s_;
  const tinygltf::Model& m_;
  std::string name_;  // the file, as messages name it
};

}  // namespace

void add_gltf_cameras(scene& s, const tinygltf::Model& m, const std::string& name,
                      const transform& placement, bool first_sets_aspect) {
  camera_collector collect(s, m, name);
  collect.first_sets_aspect = first_sets_aspect;
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
