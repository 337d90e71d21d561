#pragma once
// OpenCV camera calibrations as cv::FileStorage writes them (OpenCV's calibration sample,
// calibrateCamera scripts, ROS camera_info files), in YAML or JSON.
//
// What is read (every other top-level key -- calibration_time, avg_reprojection_error,
// extrinsic_parameters, rectification_matrix, ... -- is ignored):
//   camera matrix  camera_matrix, K or cameraMatrix: 3x3, fx 0 cx / 0 fy cy / 0 0 1, fx and fy
//                  > 0. A nonzero skew (K[0][1]) is refused: no rtvk model has one.
//   distortion     distortion_coefficients, dist_coeffs, D or distCoeffs: a 1xN or Nx1 matrix or
//                  a plain sequence, in OpenCV's order. opencv: 4, 5 or 8 coefficients (k1 k2 p1
//                  p2 [k3 [k4 k5 k6]]); opencv-fisheye: exactly 4 (k1 k2 k3 k4). 0 or a missing
//                  key: no distortion. 12 and 14 (thin prism, tilted sensor) are refused.
//   image size     image_width and image_height, or image_size / imageSize as [w, h] (a sequence
//                  or a 1x2 / 2x1 matrix), or both if they agree; required, each side a whole
//                  number in [1, max_image_side].
//   model          model or distortion_model, a string (either, or both if they agree):
//                    fisheye, opencv-fisheye, equidistant, kannala-brandt  => opencv-fisheye
//                    pinhole, opencv, plumb_bob, rational_polynomial, radtan => opencv
//                  (case does not matter).
// The model rule: a model key decides. Without one, the file is opencv-fisheye only when it also
// has a true flag `fisheye` (1 or true); otherwise it is opencv, even with 4 coefficients -- 4
// coefficients alone are OpenCV's k1 k2 p1 p2 as often as fisheye k1..k4, so the count never
// picks the model. A flag that contradicts the model key is refused.
// Each key above may be given under one of its names only.
//
// The YAML read is FileStorage's subset: an optional "%YAML:1.0" (or "%YAML 1.0") first line and
// "---", top-level `key: value` lines, scalars (numbers including .Nan, .Inf and 1.e+03, quoted
// or plain strings), flow sequences [ ... ] that may span lines, matrices as an indented block
// of rows, cols, dt and data (tagged !!opencv-matrix as FileStorage writes, or untagged as in ROS
// camera_info files), and # comments. Anything else is refused with its line. The JSON read is
// FileStorage's: matrices are objects {"type_id": "opencv-matrix", "rows", "cols", "dt", "data"};
// a camera matrix may also be written as [[..], [..], [..]].
#include <filesystem>
#include <string>

#include "camera.h"
#include "lens_intrinsics.h"

namespace rtvk {

// One camera's calibration: the model to render it with and its intrinsics.
struct calibration {
  rtvk::projection model = rtvk::projection::opencv;  // opencv or opencv_fisheye
  lens_intrinsics lens;  // size, focal lengths, principal point (pixels), distortion (k)
};

// Reads an OpenCV calibration file (at most 1 MiB): JSON when its first non-space character is
// '{', YAML otherwise. Throws usage_error naming the file.
calibration read_opencv_calibration(const std::filesystem::path& file);

// The same from the file's text; `name` is the file's name for messages, which read
// "NAME:LINE: key: what" where a line is known (YAML) and "NAME: key: what" otherwise.
// Throws usage_error.
calibration parse_opencv_calibration(const std::string& text, const std::string& name);

}  // namespace rtvk
