#pragma once
// What COLMAP's text and binary models share once their fields are read: the camera models rtvk
// renders (by the name cameras.txt writes and the id cameras.bin writes), the pose of a
// world-to-camera rotation and translation, and the names the views get (colmap_model.h says
// which).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "camera.h"

namespace rtvk {

// Where a parameter of a COLMAP camera model goes in lens_intrinsics: a slot below 0 is a focal
// length or the principal point, 0 and up the index in k (OpenCV's order).
enum colmap_slot : int { focal = -1, focal_x = -2, focal_y = -3, center_x = -4, center_y = -5 };

struct colmap_camera_model {
  std::string_view name;     // as cameras.txt writes it
  int id;                    // as cameras.bin writes it (COLMAP's CameraModelId)
  rtvk::projection model;    // what rtvk renders it with
  std::string_view params;   // the parameters' names, for messages
  std::array<int, 12> slot;  // where each parameter goes
  int count;                 // how many parameters
};

// The model cameras.txt names `name`, or nullptr for one rtvk does not render.
const colmap_camera_model* colmap_model_named(std::string_view name);

// The model cameras.bin numbers `id`, or nullptr; `count` is set to how many parameters COLMAP
// 3.8 writes for it (rendered or not: a binary file must be read past the ones refused), -1 for
// an id COLMAP does not have.
const colmap_camera_model* colmap_model_numbered(std::int64_t id, int& count);

// "SIMPLE_PINHOLE, PINHOLE, ...": the models rtvk renders, for messages.
std::string colmap_supported_models();

// Puts parameter `index` of model `m`, value `x`, where it goes in `lens`; COLMAP's principal
// point (the top-left corner at 0) moved half a pixel to rtvk's (the first pixel's center).
// Returns false for a focal length that is not > 0.
bool put_colmap_param(const colmap_camera_model& m, int index, double x, lens_intrinsics& lens);

// The pose of a camera that maps world points p to R p + t (R from the quaternion q, scaled to
// unit length here): lookfrom -R^T t, looking along its +z, vup its -y. Throws usage_error
// prefixed by `where` for a zero quaternion or a center too far out to keep the direction.
camera_pose colmap_pose(std::array<double, 4> q, const vec3& t, const std::string& where);

// Hands out the views' camera names (colmap_model.h), unique ignoring case.
class colmap_names {
 public:
  std::string take(std::string_view image_name);

 private:
  std::unordered_set<std::string> used_;       // the names handed out, lower case
  std::unordered_map<std::string, int> next_;  // a base's next suffix to try
};

}  // namespace rtvk
