#pragma once
#include "camera.h"

namespace rtvk::view {

// The viewer's camera moves, as pure functions of a pose: each returns the pose after the move.
// Rates are per pixel of mouse motion or per key press, so that a test can predict a move
// exactly (docs/viewer.md has the table).
inline constexpr double orbit_degrees_per_pixel = 0.25;  // left-drag
inline constexpr double dolly_per_wheel_step = 0.9;      // distance to the look-at point, x
inline constexpr double fly_fraction = 0.05;             // of that distance per key press
inline constexpr double fov_step_degrees = 5;            // + and -
inline constexpr double aperture_step = 1.25;            // ] multiplies, [ divides (0 <-> 0.01)

// Turns lookfrom about lookat: by right_px * orbit_degrees_per_pixel about vup (counter-clockwise
// seen from above for a drag to the right), and by up_px * orbit_degrees_per_pixel towards vup
// (a drag upwards looks more from above), never over the pole (the angle between vup and the
// eye's direction from the target stays within 1 and 179 degrees). The distance is kept.
camera_pose orbit(const camera_pose& p, double right_px, double up_px);
// Moves lookfrom and lookat together in the view plane, by pixels of a `height_px`-tall image:
// the point under the cursor at the look-at distance stays under it.
camera_pose pan(const camera_pose& p, double right_px, double up_px, int height_px);
// Moves lookfrom towards lookat: the distance times dolly_per_wheel_step per step (negative
// steps move away).
camera_pose dolly(const camera_pose& p, double steps);
// Moves lookfrom and lookat together: forward along the view, right, and up along vup, each in
// key presses of fly_fraction of the look-at distance.
camera_pose fly(const camera_pose& p, double forward, double right, double up);
// Field of view and aperture steps, within the camera's limits.
camera_pose zoom(const camera_pose& p, double steps);  // + narrows, - widens
camera_pose stop(const camera_pose& p, int steps);     // ] opens the aperture, [ closes it
// The next projection model (perspective, orthographic, equirectangular, fisheye-equidistant,
// fisheye-equisolid, then perspective again); a lens-less model gets aperture 0.
camera_pose next_projection(const camera_pose& p);

}  // namespace rtvk::view
