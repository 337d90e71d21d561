#pragma once
#include <cstdint>
#include <string>

#include "medium.h"
#include "shared_types.h"
#include "transform.h"
#include "vec3.h"

namespace rtvk {

// What bounds a medium, numbered as the shaders number it (shared_types.h).
enum class boundary_shape : std::uint32_t {
  sphere = RTVK_BOUNDARY_SPHERE,
  box = RTVK_BOUNDARY_BOX,
};

// The book's constant_medium: a convex boundary filled with fog of constant density that
// scatters by its (isotropic) material. Plain data; both backends test rays against it with the
// shared hit_medium (shaders/shared/medium.h).
struct medium {
  boundary_shape shape = boundary_shape::sphere;
  point3 center{};      // sphere: its center, scene units
  double radius = 1;    // sphere: its radius, scene units, > 0
  point3 lo{}, hi{};    // box: opposite corners before the placement, lo < hi on every axis
  transform placement;  // box: where it stands (the book's rotate_y and translate); identity
  double density = 1;   // chance of scattering per scene unit of path (the book's), > 0
  int material = 0;     // index into the scene's materials: an isotropic one
};

// The medium as hit_medium reads it (the boundary in its own space; index among the scene's
// media). Throws std::invalid_argument for a placement that cannot be inverted (check_scene
// refuses those first).
medium_geometry geometry_of(const medium& m, std::uint32_t index);

std::string shape_name(boundary_shape s);  // "sphere", "box"

}  // namespace rtvk
