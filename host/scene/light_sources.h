#pragma once
#include <string>
#include <vector>

#include "environment.h"
#include "pdf.h"
#include "render_settings.h"
#include "scene.h"

namespace rtvk {

// What the third book's importance sampling aims scattered rays at: every lamp of the scene (a
// sphere, quad or triangle whose material is diffuse_light: meshes' emissive faces included), then
// the spheres and quads marked `sampled` (the book's glass sphere), in scene order. Objects inside
// groups are not aimed at (they still emit when a path hits them). The shared kernels read these
// (shaders/shared/pdf.h); the GPU gets them as gpu_light.
std::vector<light_record> scene_lights(const scene& s);

// The lamps inside groups, each placed by every instance of its group into scene space (an
// instance's transform is static and affine: quads and triangles stay exact; a sphere only under
// a rotation and one scale, else it is left out, its light still found by the paths that hit it).
// In instance order, then spheres, quads, triangles.
std::vector<light_record> group_lamps(const scene& s);

// A lamp's power up to a constant common to all: the luminance it emits times its area, times 2
// where both sides emit (a sphere's one side is its whole surface). Uneven lamps: 0, never drawn.
double lamp_power(const light_record& l);

// What next-event estimation draws (shaders/shared/lights/nee.h): the lamps of scene_lights (its
// first entries, RTVK_LIGHT_EMITS), then group_lamps; the alias table over them all.
std::vector<light_record> scene_lamps(const scene& s);

// `auto` made definite where it is not what samples_lights says: next-event estimation where the
// scene has punctual lights (only it can draw a delta light).
void resolve_sampling(scene& s);

// Whether a render under mode `m` uses next-event estimation (sampling_mode::nee).
inline bool uses_nee(sampling_mode m) {
  return m == sampling_mode::nee;
}

// Whether a render of a scene with `lights` lights (scene_lights) samples toward them under mode
// `m`: `lights` always, `plain` never, `automatic` where there are from 1 to RTVK_MAX_LIGHTS.
bool samples_lights(std::size_t lights, sampling_mode m);
inline bool samples_lights(const scene& s, const render_settings& rs) {
  return samples_lights(scene_lights(s).size(), rs.sampling);
}

// Throws std::invalid_argument, naming `what` (the flag or field that asked), when `lights`
// sampling is asked of a scene without lights or with more than RTVK_MAX_LIGHTS.
void check_sampling(const scene& s, const render_settings& rs, const std::string& what);

// The strata a side a pixel's samples are spread over (camera_rays.h's pixel_spot): with lights
// sampling and jitter, floor(sqrt(spp)) as the book's final chapter; else 1 (the first two
// books' independent spots).
std::uint32_t pixel_strata(const render_settings& rs, bool lights);

// The name of a sampling mode, as --sampling and scene files spell it.
const char* sampling_name(sampling_mode m);

// The punctual lights' kernel records (shaders/shared/lights/punctual.h, which the callers
// include): declared here, not included, so that the many files that include this one (unity
// batches among them, whose files define their own `pi`) do not all parse the kernel.
struct punctual_record;

// "point", "spot" or "directional" (scene files' and glTF's "type").
const char* punctual_kind_name(punctual_kind k);

// The kernel's record of `l` (its spot's scale and offset, a sun's cone gap worked out in
// double): what the CPU samples and what the GPU's packing rounds to float.
punctual_record punctual_record_of(const punctual_light& l);

// Every light of `lights`, in order.
std::vector<punctual_record> punctual_records(const std::vector<punctual_light>& lights);
// The map's sampling table (environment.h's layout): its header (size, strength, rotation,
// visibility, the sampler's loop trips) and the CDFs of luminance x sin(theta), in float, exactly
// as the GPU gets it.
std::vector<float> environment_table_of(const environment_map& e);

// The map packed for the C++ kernels: its texels and its table, and the view of both they take.
struct environment_tables {
  explicit environment_tables(const environment_map& e)
      : image(e.image), table(environment_table_of(e)) {}
  std::shared_ptr<const environment_image> image;
  std::vector<float> table;
  environment_table view() const { return {image->texels.data(), table.data()}; }
};

}  // namespace rtvk
