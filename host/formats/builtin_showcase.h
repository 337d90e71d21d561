#pragma once
// The built-in scenes that read a file format, so they are made here rather than in scene/: the
// showcase (a glTF model of the project's own on a ground plane under the test environment) and
// that environment, drawn by the code that scripts/make-test-environment.py holds.
#include <memory>
#include <string>
#include <vector>

#include "scene.h"
#include "textures.h"

namespace rtvk {

// The file name that stands for the test environment in scene files and --environment:
// {"environment": {"file": "builtin:sky-sun"}}.
inline constexpr const char* builtin_sky_sun = "builtin:sky-sun";

// The test environment (docs/lighting.md): a sky gradient over a dim ground and a sun 3 degrees
// in radius, of radiance (5000, 4800, 4500), along sky_sun_direction; 256x128 texels, the same
// RGBE words as docs/scenes/sky-sun.hdr, which the script writes.
std::shared_ptr<const environment_image> sky_sun_image();
// The sun's direction in the map's own frame (before a scene's rotation): elevation 35 degrees,
// azimuth 60 degrees from +x toward +z.
vec3 sky_sun_direction();

// `rtvk render --scene showcase`: docs/scenes/showcase.glb (scripts/make-showcase-model.py,
// embedded in the binary) on a gray ground plane under the test environment, its sun casting
// the shadows, drawn with next-event estimation.
scene showcase_scene();

// The built-in scenes made here, in the order `rtvk scene list` prints them after the books'.
std::vector<std::string> format_scene_names();

}  // namespace rtvk
