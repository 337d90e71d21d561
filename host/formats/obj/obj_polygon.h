#pragma once
// An OBJ face of more than three corners as triangles, in the plane the face lies in: what
// viewers draw for a concave face (an L, a U, a ring cut open) is the face, not a fan across it.
#include <array>
#include <cstddef>
#include <vector>

#include "vec3.h"

namespace rtvk {

// The most corners a face is cut into ears for (ear clipping takes time quadratic in them, cubic at
// worst); a larger face is cut as a fan from its first corner.
inline constexpr std::size_t max_ear_clipped_corners = 256;

// Triangles covering the polygon `corners` (in order around it; the plane is the one Newell's
// normal gives), as indices into `corners`, each wound as the polygon is. A convex quad is cut
// along its shorter diagonal (what tinyobjloader does, so that such files draw as they did); any
// other face by ear clipping, which keeps a concave face's shape. A face with no area, or one
// that crosses itself where no ear is left, still gets n - 2 triangles (some without area).
std::vector<std::array<std::size_t, 3>> triangulate_polygon(const std::vector<vec3>& corners);

}  // namespace rtvk
