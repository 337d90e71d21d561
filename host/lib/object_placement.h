#pragma once
// Moving one object of a scene between renders (the library's Scene::place): the object as
// object_ids numbers it -- a sphere, a quad, a box, a triangle, a mesh file, a disk or an
// instance -- placed by a transform after the placement its scene gave it. The object's
// primitives are kept as they were first found, so that placing it again starts from them:
// placements replace each other rather than compound, and the identity puts it back.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scene.h"
#include "transform.h"

namespace rtvk {

// One object as the scene held it before any placement.
struct object_original {
  std::uint32_t id = 0;          // object_ids' number, 1 and up
  std::string kind;              // sphere, quad, box, triangle, mesh, disk or instance
  std::size_t first = 0;         // index of its first primitive in its kind's list (or instance)
  std::size_t count = 1;         // primitives
  int material = -1;             // its first primitive's material; -1: an instance
  std::uint32_t group = 0;       // an instance's group
  point3 lo{0}, hi{0};           // the box around it where the scene has it now, scene units
  shape_lists shapes;            // its primitives (find_object only): one kind's list, and its
                                 // triangles' shading
  transform instance_placement;  // an instance's own placement
};

// Object `id` of `s` as it is now, its primitives copied; nullopt where the scene has no such id.
std::optional<object_original> find_object(const scene& s, std::uint32_t id);

// Every object of the scene, in id order, without their primitives.
std::vector<object_original> list_objects(const scene& s);

// Puts `o` into `s` placed by `t` after its original placement: spheres and disks only by turns,
// moves and one scale (the reason is returned where `t` would stretch one; `s` is then
// unchanged). `s` must hold `o`'s object where find_object found it.
std::optional<std::string> place_object(scene& s, const object_original& o, const transform& t);

}  // namespace rtvk
