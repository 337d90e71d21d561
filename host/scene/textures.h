#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "shared_types.h"
#include "texture.h"
#include "vec3.h"

namespace rtvk {

// The kinds of texture, numbered as the shaders number them (shared_types.h). A solid color is
// no texture: the material's albedo.
enum class texture_type : std::uint32_t {
  checker = RTVK_TEXTURE_CHECKER,  // the book's spatial checker
  image = RTVK_TEXTURE_IMAGE,      // an image, nearest texel at the hit's (u, v)
  noise = RTVK_TEXTURE_NOISE,      // the book's Perlin noise
};

enum class noise_style : std::uint32_t {
  smooth = RTVK_NOISE_SMOOTH,          // 0.5 * (1 + noise(scale p))
  turbulence = RTVK_NOISE_TURBULENCE,  // turb(scale p)
  marble = RTVK_NOISE_MARBLE,          // 0.5 * (1 + sin(scale p.z + 10 turb(p))): the book's
};

// How an image texture reads coordinates outside [0, 1].
enum class image_wrap : std::uint32_t {
  clamp = RTVK_WRAP_CLAMP,    // the edge's texel: the book's
  repeat = RTVK_WRAP_REPEAT,  // tiled: glTF's default
  mirror = RTVK_WRAP_MIRROR,  // tiled, every other copy mirrored
};

// An image's texels as both backends read them: linear values, a byte a channel, RGBA8 with red
// in the lowest byte (alpha linear, 255 where the image has none), rows from the top.
struct texel_image {
  int width = 0;                      // texels across
  int height = 0;                     // rows
  std::vector<std::uint32_t> texels;  // width * height
};

enum class texel_encoding : std::uint32_t;  // below: how an image's bytes map to linear

// One texture of a scene: plain data (shaders/shared/texture.h says what each kind draws).
struct texture {
  texture_type type = texture_type::checker;
  double scale = 1;     // checker: a cell's size, scene units; noise: frequency
  color even{1, 1, 1};  // checker: even cells' color; noise: the color noise 1 has; image: a
                        // tint the texels are multiplied by
  color odd{0, 0, 0};   // checker: odd cells' color
  noise_style style = noise_style::marble;  // noise
  std::string file;  // image: the file read, as written in the scene file (or
                     // "builtin:planet" for the image rtvk draws itself)
  std::shared_ptr<const texel_image> image;  // image: its texels (shared by copies of a scene)
  image_wrap wrap_u = image_wrap::clamp;     // image: outside [0, 1] along u
  image_wrap wrap_v = image_wrap::clamp;     // and along v
  // image: how the file's bytes were decoded to linear (a scene file's "color_space");
  // value-initialized: texel_encoding::book, the book's gamma 2.2
  texel_encoding color_space{};
};

// The most texels an image texture may have across or down, and in all: 16384 is what most GPUs
// take for a 2D image side, and 2^26 texels (256 MiB of RGBA8) fit every device's storage
// buffer range with room for the rest of the scene.
inline constexpr int max_texture_side = 16384;
inline constexpr std::uint64_t max_texture_texels = std::uint64_t(1) << 26;
inline constexpr std::uint64_t max_texture_file_bytes = std::uint64_t(1) << 30;
// The most texels a scene's images may have together (each image counted once however many
// textures use it): 1 GiB of RGBA8, and every texel index fits 32 bits.
inline constexpr std::uint64_t max_scene_texels = std::uint64_t(1) << 28;

// How an image's bytes map to linear values: its color space.
enum class texel_encoding : std::uint32_t {
  book = 0,    // the book's rtw_image: (byte / 255)^2.2 (every image a scene file names)
  srgb = 1,    // the sRGB transfer function: glTF base color and emissive images, MTL maps
  linear = 2,  // data, not colors: glTF metallic-roughness, occlusion and normal images
};

// Reads a PNG or JPEG (8 bits a channel; what stb_image reads) and makes its colors linear by
// `encoding` (by default as the book's rtw_image does: gamma 2.2), then a byte a channel
// (floor(256 v), clamped); alpha is kept as it is (linear in every color space). Throws usage_error
// naming `name` (the scene file's path of the field) and the file: missing, unreadable, not an
// image, truncated, or larger than the limits above.
std::shared_ptr<const texel_image> load_texel_image(const std::filesystem::path& file,
                                                    const std::string& name,
                                                    texel_encoding encoding = texel_encoding::book);
// The same for an image's encoded bytes (a glTF's embedded image); `name` leads every message.
std::shared_ptr<const texel_image> decode_texel_image(
    const std::string& bytes, const std::string& name,
    texel_encoding encoding = texel_encoding::book);

// The book's linear-to-byte rule for one channel value: 0 at or below 0, 255 at or above 1,
// else floor(256 v).
std::uint8_t linear_to_byte(float v);

// The noise textures' tables (the book's perlin class), made from a seed: random unit vectors at
// the lattice points and three shuffles of 0..255. Every noise texture of a scene shares them;
// both backends read the same numbers (the GPU's rounded to float).
struct perlin_tables {
  std::array<vec3, RTVK_PERLIN_POINTS> vectors{};            // unit vectors
  std::array<std::uint32_t, 3 * RTVK_PERLIN_POINTS> perm{};  // x's, then y's, then z's
};
perlin_tables make_perlin(std::uint32_t seed);

// An image rtvk draws itself: a planet of oceans, land and ice caps in equirectangular layout
// (what the book's earth texture is), for the built-in scenes (no image file to ship).
std::shared_ptr<const texel_image> planet_image(int width, int height, std::uint32_t seed);
// The file name that stands for it in scene files: {"type": "image", "file": "builtin:planet"}.
inline constexpr const char* builtin_planet = "builtin:planet";

// A scene's textures as the kernels read them: a record each (texture.h's texture_record, an
// image's `first` its offset in `texels`) and every image's texels one after another, each image
// once however many textures use it.
struct packed_textures {
  std::vector<texture_record> records;  // by texture index
  std::vector<std::uint32_t> texels;    // the images', in texture order
};
packed_textures pack_textures(const std::vector<texture>& textures);

// An environment map's texels as both backends read them (shaders/shared/lights/environment.h):
// Radiance RGBE words, row by row from the top of the image.
struct environment_image {
  int width = 0;                      // texels in a row
  int height = 0;                     // rows
  std::vector<std::uint32_t> texels;  // RGBE, width x height
};

// What escaping rays see instead of the sky (scene files' "environment", --environment).
struct environment_map {
  std::string file;                                // as the scene file or the flag names it
  std::shared_ptr<const environment_image> image;  // never null in a scene
  double rotation = 0;                             // degrees about +y (docs/lighting.md)
  double strength = 1;                             // multiplies every texel's radiance, >= 0
  bool visible = true;  // camera rays that escape see it; false: they see the scene's sky
};

// The device limit an environment map is held to: lavapipe's storage-buffer range, 128 MiB, for
// its texels (4 bytes each) and for its sampling table (4 bytes an entry: (width + 2) x height +
// 9). 6144x3072 fits; 8192x4096 does not (its table is 20 KiB over).
inline constexpr std::uint64_t max_environment_buffer_bytes = std::uint64_t(128) << 20;
// The largest environment file read, bytes.
inline constexpr std::uint64_t max_environment_file_bytes = std::uint64_t(1) << 30;

// Throws usage_error, naming `where`, unless a width x height map fits the limit above.
void check_environment_size(std::uint64_t width, std::uint64_t height, const std::string& where);

// Radiance's RGBE word of a linear RGB texel (each in [0, 2^127)): bits 0-23 the channels'
// mantissas, 24-31 the shared exponent; 0 (black) where the largest channel is below 2^-118. What a
// Radiance file decodes to (stb_image's float) encodes back exactly.
std::uint32_t encode_rgbe(float r, float g, float b);

// An environment image from linear float RGB, row by row from the top. Throws usage_error,
// naming `where`, for a texel that is not finite or is negative, or an image past the limit.
std::shared_ptr<const environment_image> environment_from_rgb(int width, int height,
                                                              const std::vector<float>& rgb,
                                                              const std::string& where);

std::string type_name(texture_type t);  // "checker", "image", "noise"
std::string style_name(noise_style s);  // "smooth", "turbulence", "marble"
std::string wrap_name(image_wrap w);    // "clamp", "repeat", "mirror"

}  // namespace rtvk
