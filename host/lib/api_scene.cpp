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

void Scene::set_material(const std::string& name, const std::string& material_json) {
  translate([&] {
    // The material read as a scene file reads one: a scene of one sphere made of it.
    const scene one = parse_scene_json(
        "{\"materials\": {\"m\": " + material_json +
            "}, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]}",
        "material");
    const auto made = std::find_if(one.materials.begin(), one.materials.end(),
                                   [](const named_material& m) { return m.name == "m"; });
    for (named_material& m : impl_->s.materials)
      if (m.name == name) {
        m.m = made->m;
        ++impl_->version;
        return 0;
      }
    throw usage_error("material " + name + ": the scene has no material of that name");
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
