#pragma once
#include <string>
#include <vector>

#include "aov_image.h"
#include "object_ids.h"
#include "render_settings.h"
#include "shared_types.h"

namespace rtvk {

// The AOVs `which` of a window from what a pass found at each pixel (render_aov_cpu or the
// device's aov.comp): ids numbered by `ids`, materials from 1.
aov_image aov_from(const std::vector<gpu::gpu_aov>& found, const object_ids& ids, unsigned which,
                   const render_window& win);

// Where a PNG or PPM render's AOV goes: out.png -> out.depth.exr (the output's name without its
// extension, then the AOV's name).
std::string aov_path(const std::string& output, aov_bit which);

// --aov's list as an aov_bit mask (0 where empty); throws usage_error naming the flag.
unsigned aov_flag(const std::string& list);

// --backend both: whether the device's AOVs are the CPU's -- the same object and material at
// every pixel but on an edge of the CPU's id image (a pixel whose neighbor shows another object
// or material: where a ray grazes two surfaces, float and double may pick either), the same
// distance to 1e-4 relative where both hit the same object. Prints a line saying so.
bool aovs_agree(const std::vector<gpu::gpu_aov>& gpu, const std::vector<gpu::gpu_aov>& cpu,
                const object_ids& ids, int width, const std::string& label);

}  // namespace rtvk
