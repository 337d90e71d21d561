#pragma once
#include <optional>
#include <string>

#include "camera.h"
#include "scene.h"

namespace rtvk {

// The settings a run overrides in a scene (--width, --spp, --lookfrom, ...), shared by
// `rtvk render` and `rtvk bench`. Each applies only when given; values are as typed, checked
// when applied, and the messages name the flags. scene_flags fills it from the command line.
struct scene_overrides {
  std::optional<int> width;                   // image width, pixels
  std::optional<std::string> aspect;          // aspect ratio as typed, W:H or a decimal
  std::optional<int> spp;                     // samples per pixel
  std::optional<int> depth;                   // most bounces per path
  std::optional<long long> seed;              // random seed, 0 to 2^32 - 1
  std::optional<std::string> lookfrom;        // camera position as typed, x,y,z
  std::optional<std::string> lookat;          // point looked at as typed, x,y,z
  std::optional<std::string> vup;             // up direction as typed, x,y,z
  std::optional<double> vfov;                 // vertical field of view, degrees
  std::optional<double> aperture;             // lens diameter, scene units (0: pinhole)
  std::optional<double> focus_dist;           // distance in focus, scene units
  std::optional<std::string> projection;      // camera model, by name (projection_from_name)
  std::optional<double> fisheye_fov;          // fisheye field of view, degrees
  std::optional<std::string> shutter;         // OPEN:CLOSE as typed, seconds after the frame's time
  std::optional<double> orbit;                // seconds per turn of the built-in orbit path
  std::optional<std::string> sampling;        // plain, lights, nee or auto (sampling_mode)
  std::optional<std::string> view_transform;  // standard, filmic, agx, linear or gamma
  std::optional<double> exposure;             // EV, -16 to 16
  std::optional<std::string> calibration;     // OpenCV calibration file (calibration_file.h)
  std::optional<std::string> intrinsics;      // fx,fy,cx,cy as typed, pixels
  std::optional<std::string> distortion;      // the model's coefficients as typed, comma-separated
  std::optional<std::string> rolling_shutter;  // DIRECTION:SECONDS as typed
  std::optional<std::string> colmap;           // a COLMAP text model's folder: one camera per view
  std::optional<std::string> environment;      // FILE[:STRENGTH] as typed: an environment map

  // Replaces the scene's cameras with a COLMAP model's views (--colmap), and sets the image size
  // from the calibration or the views when no --width is given. Before the cameras are chosen.
  void apply_cameras(scene& s) const;

  // The scene's settings with the overrides applied, to every camera in s.cameras (narrow them
  // to the chosen ones first). Throws usage_error naming the flag.
  void apply(scene& s) const;

  // The camera for `pose` in the scene, for the frame at `frame_time` seconds; an impossible
  // combination (a height over the limit, a camera looking at itself) is a usage_error naming
  // the flags involved and `what` (the camera).
  camera make_camera(const scene& s, const camera_pose& pose, const std::string& what,
                     double frame_time = 0) const;
};

// An aspect ratio that gives exactly `height` rows at `width` (camera's max(1, int(w / a))):
// width / height itself can round to one row fewer.
double exact_aspect(int width, int height);

}  // namespace rtvk
