#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "camera.h"
#include "camera_path.h"
#include "disk.h"
#include "material.h"
#include "object_group.h"
#include "quad.h"
#include "render_settings.h"
#include "sphere.h"
#include "textures.h"
#include "transform.h"
#include "triangle.h"
#include "volumes.h"

namespace rtvk {

// The light that reaches a ray that hits nothing: a blend from the horizon color (looking
// straight down) to the zenith color (straight up). The defaults are the lesson's sky; equal
// colors make a uniform sky, as a white-furnace test wants.
struct sky {
  color horizon{1.0, 1.0, 1.0};  // linear RGB seen along -y, blending to...
  color zenith{0.5, 0.7, 1.0};   // ...this along +y
};

// Punctual lights (issue 46): KHR_lights_punctual's point, spot and directional lights, and a
// sun (a directional light with an angular diameter). Data here; the kernel that samples them is
// shaders/shared/lights/punctual.h (light_sources.h makes its records), their units
// docs/lighting.md's "Punctual lights".
enum class punctual_kind { point, spot, directional };

// A light without size, or a sun. Angles are in degrees, as scene files write them (glTF's
// radians are converted when read).
struct punctual_light {
  punctual_kind kind = punctual_kind::point;
  std::string name;             // the glTF light's or node's name, for messages; may be empty
  point3 position{0, 0, 0};     // point, spot: where it stands, scene units
  vec3 direction{0, 0, -1};     // spot, directional: the way its light travels (any length)
  color tint{1, 1, 1};          // linear RGB (glTF's "color")
  double intensity = 1;         // point, spot: candela; directional: lux
  double inner_cone = 0;        // spot: degrees off `direction` where the falloff starts
  double outer_cone = 45;       // spot: degrees where it reaches 0 (glTF's default pi / 4)
  double angular_diameter = 0;  // directional: degrees; 0 a delta light, > 0 a sun's disk
};

struct named_camera {
  std::string name;  // how --camera and {camera} in -o refer to it
  camera_path path;  // where it stands at each time
};

struct named_material {
  std::string name;  // how spheres refer to it in scene files
  material m;        // its optics
};

// What to render, independent of the backend: the CPU builds its hittables from it (cpu/world.h),
// the GPU packs the same spheres and materials into storage buffers (gpu/scene/packing.h).
// A run of consecutive quads or triangles of a scene that make one object.
struct primitive_run {
  bool triangles;       // of s.triangles; else of s.quads
  std::uint32_t first;  // index of the first
  std::uint32_t count;  // how many
};

struct scene : shape_lists {
  std::string name;                                    // built-in name or the file it came from
  std::vector<named_camera> cameras{{"default", {}}};  // at least one; the first is the
                                                       // default; the lesson's camera unless set
  render_settings render;                              // default image size, samples, depth, ...
  rtvk::sky sky;                                       // what rays that escape see
  // What they see instead, where given (camera rays see the sky where it is not visible).
  std::optional<environment_map> environment;
  std::vector<named_material> materials;  // objects index into this
  // The objects, one list per shape (shape_lists, the base: spheres, quads, triangles and their
  // shading, disks), hit as if in one list in that order, an exact tie going to the later.
  // Groups of objects stored once, and their placements: hit after every object above, in
  // instance order, each instance's objects in its group's order (spheres, quads, triangles).
  std::vector<object_group> groups;
  std::vector<instance> instances;
  // What colors materials (their `texture` indices) and what fills space.
  std::vector<texture> textures;  // checker, image and noise textures
  std::uint32_t noise_seed = 0;   // makes the noise textures' tables (make_perlin)
  std::vector<medium> media;      // constant-density media, tested after every object
  // Point, spot and directional lights and suns (punctual_light above): lit by next-event
  // estimation, never hit by a path (a sun is seen by rays that escape).
  std::vector<punctual_light> punctual_lights;
  // Objects of several primitives, one object each to --aov object-id (object_ids.h): a box's
  // six quads, a mesh file's triangles.
  std::vector<primitive_run> compounds;
  // What the loaders drew otherwise than the file asks (an optional extension ignored, a missing
  // MTL drawn gray): one line each, said once; the CLI prints them to stderr as warnings.
  std::vector<std::string> warnings;
  time_span motion;  // the instants rays may sample, seconds: BVHs bound moving spheres over it
                     // (render plans widen it to every frame's shutter; default [0, 1])
};

std::vector<material> scene_materials(const scene& s);

// Objects stored, of every kind: spheres + quads + triangles + disks, the groups' included once
// each (however many instances place them).
inline std::size_t object_count(const scene& s) {
  std::size_t n = shape_count(s);
  for (const object_group& g : s.groups) n += object_count(g);
  return n;
}

// The book's box: the six quads of the axis-aligned box with opposite corners a and b, in its
// order (front, right, back, left, top, bottom), each placed by `t`.
void add_box(scene& s, const point3& a, const point3& b, int material, const transform& t = {});

// Whether some texture of the scene reads the hits' texture coordinates (an image): only then do
// the searches find spheres' (u, v), which costs two inverse trigonometric functions a hit.
bool scene_reads_uv(const scene& s);

// Whether some sphere of the scene moves.
bool scene_moves(const scene& s);

// The instants every camera's shutter spans at `time` (seconds): what a view of the scene at
// that time, from any of its cameras, samples.
time_span shutter_span(const scene& s, double time);

// Throws std::invalid_argument when the scene has moving spheres and `cam`'s shutter samples
// instants outside s.motion, the span its BVHs bound them over: a program error (render plans
// widen the span to every frame), never a silently culled sphere.
void check_motion_span(time_span motion, bool moves, const camera& cam);

// The first camera's path: the one a render uses unless --camera picks others.
inline camera_path& main_camera(scene& s) {
  return s.cameras.front().path;
}
inline const camera_path& main_camera(const scene& s) {
  return s.cameras.front().path;
}

// The largest coordinate or radius a scene may hold: the GPU squares them in float, whose range
// ends at 3.4e38, so anything near sqrt(3.4e38) = 1.8e19 would overflow there.
inline constexpr double max_scene_coordinate = 1e18;

// Throws usage_error, naming the object, when an object names a material that does not exist,
// or has a coordinate that is not finite or beyond max_scene_coordinate, or a sphere a radius
// <= 0, or a quad parallel edges.
void check_scene(const scene& s);

// The most objects (spheres, quads, triangles and disks together) a scene may hold: a BVH leaf
// keeps 28 bits for an object's position in its kind's array.
inline constexpr std::size_t max_scene_objects = std::size_t(1) << 28;

// The most media a scene may hold: every ray tests each of them (no BVH over media).
inline constexpr std::size_t max_scene_media = 64;
// Punctual lights one scene may hold: next-event estimation picks among them, and a ray that
// escapes tests every sun (punctual.h's sun_radiance).
inline constexpr std::size_t max_punctual_lights = 1024;

// The most spheres spheres:N builds.
inline constexpr std::uint32_t max_scene_spheres = 4'000'000;

// The built-in scene of that name (seed, materials, book-final, or spheres:N); throws usage_error
// naming the choices when there is none.
scene builtin_scene(std::string_view name);
std::vector<std::string> builtin_scene_names();

}  // namespace rtvk
