#pragma once
// Scenes of many lamps for the light tree's tests (tests/cpu/test_light_tree.cpp, tests/gpu/
// test_gpu_light_tree.cpp): the Cornell box with its lamp replaced.
#include <random>
#include <string>

#include "object_group.h"
#include "render_helpers.h"
#include "scene.h"

namespace rtvk::test {

// The Cornell box with its lamp replaced by `count` small emissive triangles scattered under the
// ceiling, turned every way, every other one one-sided, in three colors; spheres and quads among
// them where `mixed` (every tenth a sphere, every tenth after it a quad).
inline scene many_lamps(int count, bool mixed, int width, int spp) {
  scene s = test::small_scene("cornell-box", width, spp);
  s.render.spp = spp;
  std::erase_if(s.quads, [&](const quad& q) {
    return s.materials[std::size_t(q.material)].m.type == material_type::diffuse_light;
  });
  const int first = int(s.materials.size());
  for (int k = 0; k < 6; ++k) {
    material m{material_type::diffuse_light, color(k % 3 == 0 ? 40 : 12, k % 3 == 1 ? 40 : 12, 20),
               0, 1.5, -1};
    m.one_sided = k % 2 == 1;
    s.materials.push_back({"lamp" + std::to_string(k), m});
  }
  std::mt19937_64 gen(46);
  std::uniform_real_distribution<double> x(120, 430), y(420, 540), z(120, 430), e(-12, 12);
  for (int k = 0; k < count; ++k) {
    const point3 at(x(gen), y(gen), z(gen));
    const int material = first + k % 6;
    if (mixed && k % 10 == 0) {
      s.spheres.push_back(sphere(at, 4, material));
    } else if (mixed && k % 10 == 1) {
      s.quads.push_back({at, vec3(e(gen), e(gen), e(gen)), vec3(e(gen), e(gen), e(gen)), material});
    } else {
      triangle t;
      t.p = {at, at + vec3(e(gen), e(gen), e(gen)), at + vec3(e(gen), e(gen), e(gen))};
      t.material = material;
      s.triangles.push_back(t);
    }
  }
  return s;
}

// A group holding a lamp quad and a lamp sphere in the Cornell box (its own lamp gone), placed
// three times: turned and scaled alike, mirrored, and stretched (the sphere an ellipsoid there).
inline scene grouped_lamps(int width) {
  scene s = small_scene("cornell-box", width, 1);
  std::erase_if(s.quads, [&](const quad& q) {
    return s.materials[std::size_t(q.material)].m.type == material_type::diffuse_light;
  });
  const int lamp = int(s.materials.size());
  s.materials.push_back({"grouped", {material_type::diffuse_light, color(30, 25, 20), 0, 1.5, -1}});
  object_group g;
  g.name = "lamps";
  g.quads.push_back({point3(-20, 0, -20), vec3(40, 0, 0), vec3(0, 0, 40), lamp});
  g.spheres.push_back(sphere(point3(0, -30, 0), 12, lamp));
  s.groups.push_back(g);
  s.instances.push_back({0, make_transform(vec3(1.5), vec3(1, 0, 0), 150, vec3(200, 500, 250))});
  s.instances.push_back(
      {0, make_transform(vec3(-1, 1, 1), vec3(0, 1, 0), 30, vec3(380, 520, 300))});
  s.instances.push_back({0, make_transform(vec3(1, 2, 1), vec3(0, 0, 1), 10, vec3(150, 450, 400))});
  return s;
}

}  // namespace rtvk::test
