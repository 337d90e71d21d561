#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtvk {

// The ground truth --aov writes beside the image (docs/aov.md), one bit each.
enum aov_bit : unsigned {
  aov_depth = 1,        // "distance" (along the camera ray) and "Z" (along the camera's axis)
  aov_normal = 2,       // "N.X", "N.Y", "N.Z": world-space shading normal, facing the camera
  aov_albedo = 4,       // "albedo.R", "albedo.G", "albedo.B": the material's color there
  aov_object_id = 8,    // "object_id": 1, 2, ... (object_ids.h); 0 where nothing is hit
  aov_material_id = 16  // "material_id": the material's index + 1; 0 where nothing is hit
};

// The names --aov takes, in bit order: depth, normal, albedo, object-id, material-id.
std::string aov_names();
// The bits of a comma-separated list of those names; nothing for an unknown or empty name.
std::optional<unsigned> parse_aov_list(const std::string& text);
// The name of one bit (for file names: out.png -> out.depth.exr).
std::string aov_name(aov_bit b);

// The AOVs of a window of pixels, row-major from its top row; only the asked-for ones filled.
struct aov_image {
  unsigned which = 0;                      // aov_bit mask
  int width = 0;                           // the window's, pixels
  int height = 0;                          // pixels
  std::vector<float> distance;             // scene units; +inf where nothing is hit
  std::vector<float> depth;                // z depth, scene units; +inf where nothing is hit
  std::vector<float> normal;               // three a pixel, unit; 0 where nothing is hit
  std::vector<float> albedo;               // three a pixel, linear; 0 where nothing is hit
  std::vector<std::uint32_t> object_id;    // 0: nothing
  std::vector<std::uint32_t> material_id;  // 0: nothing
};

}  // namespace rtvk
