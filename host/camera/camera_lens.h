#pragma once
#include <optional>

#include <glm/vec2.hpp>

#include "camera.h"

namespace rtvk {

// The calibrated models' part of the camera's precomputed frame: intrinsics in the rendered
// image's pixels (scaled from the size they were calibrated at), distortion, and the field where
// the lens's inverse is defined. Throws std::invalid_argument for intrinsics that are not finite
// or positive, a calibration whose aspect ratio is not the render's, or an opencv distortion that
// does not invert at some pixel of the image (docs/camera.md says how that is found).
void setup_lens(const camera_pose& pose, int width, int height, camera_frame& f);

// The forward projection of a calibrated model: where camera-frame point (x right, y down, z
// forward) c lands, in pixels; nothing outside the model's field.
std::optional<glm::dvec2> project_calibrated(const camera_frame& f, const glm::dvec3& c);

}  // namespace rtvk
