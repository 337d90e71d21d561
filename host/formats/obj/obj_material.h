#pragma once
// An MTL material as rtvk's pbr material (the glTF metallic-roughness model, pbr_material.h),
// statement by statement as Blender's OBJ importer maps MTL to its Principled BSDF
// (source/blender/io/wavefront_obj/importer/obj_import_mtl.cc, Blender 4.x). The whole table is
// docs/mesh-formats.md's "OBJ and MTL":
//   Kd             base color (0.8, Blender's default, where absent; 1 for glass)
//   Ks             level = 2 mean(Ks) (Blender's Specular IOR Level = mean(Ks), which its glTF
//                  exporter doubles): specular = min(1, level), specular_color = max(1, level);
//                  mean(Ks) absent: 1 with illum 2, else 0
//   Ns             roughness = 1 - sqrt(Ns / 1000) (Ns clamped to [0, 1000]); absent: 0 with
//                  illum 2, else 1
//   Pr, Pm         roughness, metallic, over what Ns and illum say
//   illum          3, 5, 8 (reflection on): metallic = mean(Ka) (1 where Ka is absent); 4, 6, 7,
//                  9 (refraction on): transmission 1 (glass), d not drawn again
//   Ni             ior (at least 1; 1.5 where absent or <= 0)
//   Ke             emission, any strength (a lamp: McGuire's Cornell box's "light" is Ke 17 12 4)
//   d, Tr          opacity d (Tr = 1 - d where there is no d), alpha-blended below 1
//   Ps             sheen color (Ps, Ps, Ps), sheen roughness 0.5 (Blender's default)
//   Pc, Pcr        clearcoat = 0.25 Pc (Blender's compatibility factor), its roughness Pcr (0.03,
//                  Blender's default, where absent)
//   aniso, anisor, Tf, Ka (but for metallic), map_Ks, map_Ns: not read
// The maps (map_Kd, map_Ke, map_d, map_Pr/map_Pm, map_Ps, norm/map_Bump/bump) are image files:
// mesh_obj.cpp reads them.
#include <map>
#include <set>
#include <string>

#include <tiny_obj_loader.h>

#include "material.h"

namespace rtvk {

// The statements (first words: "Kd", "Ns", "map_Kd"...) each material of an MTL text has, by
// its name as tinyobjloader reads it: what tells a statement set to its default from one absent.
using mtl_statements = std::map<std::string, std::set<std::string>>;
mtl_statements statements_of(const std::string& mtl_text);

// The material `m` is drawn as, without its maps; `given` holds its statements.
material mtl_material(const tinyobj::material_t& m, const std::set<std::string>& given);

}  // namespace rtvk
