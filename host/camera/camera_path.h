#pragma once
#include <string>
#include <vector>

#include "camera.h"

namespace rtvk {

// One stop of a keyframed path.
struct camera_keyframe {
  double time = 0;   // seconds from the start of the animation
  camera_pose pose;  // where the camera stands and how its lens is set at that time
};

enum class camera_motion {
  fixed,      // the pose, at every time
  orbit,      // the pose turned about the up axis through the look-at point
  keyframes,  // interpolated between keyframes, held before the first and after the last
};

// How a camera moves over time. Orientation between keyframes is interpolated as a rotation
// (spherical linear interpolation of the camera's frame), so the up vector is always
// perpendicular to the view and the picture never flips, even where the path looks straight
// down past the keyframes' up vectors.
struct camera_path {
  camera_motion motion = camera_motion::fixed;
  camera_pose pose;                        // fixed: the pose; orbit: the pose at time 0
  double orbit_period = 0;                 // orbit: seconds per turn, > 0, counter-clockwise
                                           // seen from above (from +vup)
  std::vector<camera_keyframe> keyframes;  // keyframes: at least one, times strictly increasing

  // The pose at `seconds`. Keyframe times and time 0 of an orbit give their pose exactly.
  camera_pose at(double seconds) const;
};

// Throws std::invalid_argument when the path cannot produce a view at some time: a pose that
// does not define one (see camera), an orbit period that is not finite and > 0, no keyframes,
// or keyframe times that are not finite and strictly increasing.
void check_camera_path(const camera_path& path);

// Camera names become parts of file names ({camera} in -o): letters, digits, '-', '_' and '.',
// not starting with '.', at most 64 characters, and not "all" (which --camera reserves).
bool valid_camera_name(const std::string& name);

}  // namespace rtvk
