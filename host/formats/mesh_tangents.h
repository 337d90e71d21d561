#pragma once
#include <cstddef>

#include "scene.h"

namespace rtvk {

// Whether material m reads a tangent-space normal map (its own or its clearcoat's): the triangles
// that need tangents. Others keep none, and pay nothing for them.
bool normal_mapped_material(const material& m);

// Tangents for the triangles s.triangles[first, end) that have vertex normals and uv, no tangents
// yet and a normal-mapped material, generated per glTF's convention (MikkTSpace where it
// matters): each face's dp/du and dp/dv from its uv, accumulated per vertex over the faces that
// share its position, normal, uv and handedness (vertices split at uv seams and at mirrored uv),
// each face weighted by its angle at the vertex and projected on the vertex normal's plane; then
// made perpendicular to the vertex normal and unit, and w = +1 or -1 as the bitangent
// cross(n, t) agrees with dp/dv or not. Faces without a uv area (degenerate uv) add nothing; a
// vertex nothing reaches gets some tangent perpendicular to its normal.
void generate_tangents(scene& s, std::size_t first);

}  // namespace rtvk
