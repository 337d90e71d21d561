#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "confined_path.h"
#include "scene.h"

namespace rtvk {

// The largest scene file rtvk reads. A file of 4,000,000 spheres as `rtvk scene dump` writes it
// is about 560 MB; a larger file is refused (usage_error) rather than read without end.
inline constexpr std::uint64_t max_scene_file_bytes = std::uint64_t(1) << 30;

// Reads a JSON scene file (docs/scene-format.md). Any problem -- unreadable file, invalid JSON,
// a missing or unknown field, a wrong type, a non-finite number, a bad radius, an unknown
// material, a file it names outside the folder `access` allows -- throws usage_error naming the
// file and the line and column or the JSON path. The files it names are relative to its folder
// (parse_scene_json: file_name's).
scene load_scene_file(const std::filesystem::path& path, const file_access& access = {});
scene parse_scene_json(const std::string& text, const std::string& file_name,
                       const file_access& access = {});

// The scene as JSON in the same format; reading it back gives the identical scene.
std::string dump_scene_json(const scene& s);

// One pose as a scene file's camera object, on one line ({"lookfrom": ...}); read back as a
// scene's "camera" it is the same pose.
std::string dump_camera_json(const camera_pose& pose);

// --scene VALUE names a file (rather than a built-in) when it ends in .json or contains a '/'.
bool names_scene_file(const std::string& value);

// Every built-in scene's name, as `rtvk scene list` prints them: the books' (builtin_scene_names)
// and those made here, which read a model (format_scene_names: showcase).
std::vector<std::string> scene_names();

// The built-in scene or the file that `value` names (a scene file or a mesh file, the files it
// names confined as `access` says).
scene load_scene(const std::string& value, const file_access& access = {});

// Reads a Radiance .hdr (stb_image) or OpenEXR .exr file (told apart by content) as an
// environment image; "builtin:sky-sun" is the test environment, drawn (sky_sun_image). Throws
// usage_error naming `name` (the field or flag) and the file: missing, unreadable, not an HDR
// image, truncated, with a texel not finite or negative, or too large.
std::shared_ptr<const environment_image> load_environment_image(const std::filesystem::path& file,
                                                                const std::string& name);

// The same for a file's bytes (the fuzzer's entry); `where` leads every message.
std::shared_ptr<const environment_image> decode_environment_image(const std::string& bytes,
                                                                  const std::string& where);

}  // namespace rtvk
