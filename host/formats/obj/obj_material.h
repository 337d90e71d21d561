#pragma once
// An MTL material as rtvk draws it today (issue 45 brings a PBR material model). The whole table,
// MTL statement by statement, is docs/mesh-formats.md's "OBJ and MTL":
//   Kd             the albedo (diffuse, or metal's color with Pm >= 0.5), clamped to [0, 1]
//   Ks             metal's color with illum 3 (reflection on), else not drawn
//   Ns             not drawn (a Phong exponent; rtvk's metal is blurred by Pr, its roughness)
//   illum          4, 6, 7, 9 (refraction): glass of index Ni; 3: metal of Ks; others diffuse
//   Ke             emission, any strength (a lamp: McGuire's Cornell box's "light" is Ke 17 12 4)
//   d, Tr          opacity d (Tr = 1 - d where there is no d), alpha-blended below 1
// The maps (map_Kd, map_Ke, map_d) are image files: mesh_obj.cpp reads them.
#include <tiny_obj_loader.h>

#include "material.h"

namespace rtvk {

// The material `m` is drawn as, without its maps.
material mtl_material(const tinyobj::material_t& m);

}  // namespace rtvk
