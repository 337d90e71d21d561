// The library's scenes and cameras (rtvk.h): what `rtvk render` reads and the camera it draws
// with no flags, built by the same functions.
#include <algorithm>
#include <cmath>

#include "api_impl.h"
#include "camera_lens.h"
#include "errors.h"
#include "precision_flag.h"
#include "scene_file.h"
#include "version.h"

namespace rtvk::api {

Scene::Scene(std::shared_ptr<impl> i) : impl_(std::move(i)) {}

Scene::Scene(const std::string& name_or_file)
    : impl_(std::make_shared<impl>(
          translate([&] { return impl::checked(load_scene(name_or_file)); }))) {
  impl_->builtin = precision_for("auto", name_or_file) == cpu_precision::reference;
}

Scene Scene::from_json(const std::string& json, const std::string& folder) {
  const std::string file = (std::filesystem::path(folder) / "scene.json").string();
  return Scene(std::make_shared<impl>(
      translate([&] { return impl::checked(parse_scene_json(json, file)); })));
}

std::string Scene::to_json() const {
  return dump_scene_json(impl_->s);
}

std::string Scene::name() const {
  return impl_->s.name;
}

std::vector<std::string> Scene::camera_names() const {
  std::vector<std::string> names;
  for (const named_camera& c : impl_->s.cameras) names.push_back(c.name);
  return names;
}

namespace {

// Drops the textures no material reads any more (an edit replaced the material that did), so that
// a loop of edits does not grow the scene.
void drop_unread_textures(scene& s) {
  std::vector<int> index(s.textures.size(), -1);
  for (named_material& m : s.materials)
    for_each_texture(m.m, [&](int t) {
      if (t >= 0) index[std::size_t(t)] = 0;
    });
  std::vector<texture> kept;
  for (std::size_t k = 0; k < s.textures.size(); ++k)
    if (index[k] == 0) {
      index[k] = int(kept.size());
      kept.push_back(std::move(s.textures[k]));
    }
  s.textures = std::move(kept);
  for (named_material& m : s.materials)
    for_each_texture(m.m, [&](int& t) {
      if (t >= 0) t = index[std::size_t(t)];
    });
}

}  // namespace

void Scene::set_material(const std::string& name, const std::string& material_json) {
  translate([&] {
    // The material read as a scene file reads one: a scene of one sphere made of it, whose
    // textures join this scene's.
    scene one = parse_scene_json(
        "{\"materials\": {\"m\": " + material_json +
            "}, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]}",
        "material");
    const auto made = std::find_if(one.materials.begin(), one.materials.end(),
                                   [](const named_material& m) { return m.name == "m"; });
    scene& s = impl_->s;
    const auto target = std::find_if(s.materials.begin(), s.materials.end(),
                                     [&](const named_material& m) { return m.name == name; });
    if (target == s.materials.end())
      throw usage_error("material " + name + ": the scene has no material of that name");
    const int first = int(s.textures.size());
    for_each_texture(made->m, [&](int& t) {
      if (t >= 0) t += first;
    });
    const material before = target->m;
    std::vector<texture> textures_before = s.textures;  // images are shared, not copied
    for (texture& t : one.textures) s.textures.push_back(std::move(t));
    target->m = made->m;
    drop_unread_textures(s);
    try {
      check_scene(s);  // what a scene file with this material would be refused for
    } catch (const usage_error& e) {
      target->m = before;
      s.textures = std::move(textures_before);
      throw usage_error("material " + name + ": " + e.what());
    }
    ++impl_->version;
    return 0;
  });
}

std::vector<Scene::Object> Scene::objects() const {
  std::vector<Object> out;
  const scene& s = impl_->s;
  for (const object_original& o : list_objects(s)) {
    Object b{o.id, o.kind, "", "", o.count, {o.lo.x, o.lo.y, o.lo.z}, {o.hi.x, o.hi.y, o.hi.z}};
    if (o.material >= 0) b.material = s.materials[std::size_t(o.material)].name;
    if (o.kind == "instance") b.group = s.groups[o.group].name;
    out.push_back(std::move(b));
  }
  return out;
}

namespace {

// A placement from 16 numbers (a 4x4, row-major, last row 0 0 0 1) or 12 (its first 3 rows).
transform placement_of(const std::vector<double>& m) {
  if (m.size() != 12 && m.size() != 16)
    throw usage_error("matrix: expected 12 or 16 numbers (row-major), got " +
                      std::to_string(m.size()));
  for (double v : m)
    if (!std::isfinite(v)) throw usage_error("matrix: expected finite numbers");
  if (m.size() == 16 && (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1))
    throw usage_error("matrix: the last row must be 0 0 0 1 (an affine placement)");
  transform t;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) t.linear[col][row] = m[std::size_t(4 * row + col)];
    t.offset[row] = m[std::size_t(4 * row + 3)];
  }
  if (const std::optional<std::string> why = degenerate(t))
    throw usage_error("matrix: the transform cannot place anything: " + *why);
  return t;
}

}  // namespace

void Scene::place(std::uint32_t id, const std::vector<double>& matrix) {
  translate([&] {
    const transform t = placement_of(matrix);
    auto kept = impl_->placed.find(id);
    if (kept == impl_->placed.end()) {
      std::optional<object_original> found = find_object(impl_->s, id);
      if (!found)
        throw usage_error("object " + std::to_string(id) + ": the scene has objects 1 to " +
                          std::to_string(list_objects(impl_->s).size()));
      kept = impl_->placed.emplace(id, impl::placed_object{std::move(*found), transform{}}).first;
    }
    impl::placed_object& p = kept->second;
    if (const std::optional<std::string> why = place_object(impl_->s, p.original, t))
      throw usage_error("object " + std::to_string(id) + ": " + *why);
    try {
      check_scene(impl_->s);  // coordinates past what the renderers hold, faces with no area
    } catch (const usage_error& e) {
      place_object(impl_->s, p.original, p.now);  // back where it was
      throw usage_error("object " + std::to_string(id) + ": " + e.what());
    }
    p.now = t;
    ++impl_->version;
    return 0;
  });
}

scene Scene::impl::checked(scene s) {
  check_scene(s);
  return s;
}

Camera Camera::from_scene(const Scene& sc, const std::string& name) {
  return translate([&] {
    const scene& s = sc.impl_->s;
    const named_camera* chosen = &s.cameras.front();
    if (!name.empty()) {
      chosen = nullptr;
      for (const named_camera& c : s.cameras)
        if (c.name == name) chosen = &c;
      if (!chosen) throw usage_error("camera " + name + ": the scene has no camera of that name");
    }
    const scene_overrides none;
    return Camera{std::make_shared<const impl>(
        impl{none.make_camera(s, chosen->path.at(0), "camera " + chosen->name)})};
  });
}

int Camera::width() const {
  return impl_->cam.image_width();
}

int Camera::height() const {
  return impl_->cam.image_height();
}

std::vector<std::string> builtin_scenes() {
  return scene_names();
}

std::string version() {
  return version_string;
}

}  // namespace rtvk::api
