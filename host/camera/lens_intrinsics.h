#pragma once
#include <array>

namespace rtvk {

// A calibrated camera's intrinsics, in OpenCV's conventions (docs/camera.md): image x to the
// right, y down, pixel (0, 0)'s center at (0, 0). The camera models opencv, opencv-fisheye,
// fisheye-polynomial and cylindrical read them; the ideal models ignore them.
struct lens_intrinsics {
  int width = 0;               // image width the intrinsics were calibrated at, pixels; 0: unset
  int height = 0;              // image height they were calibrated at, pixels
  double fx = 0;               // focal length along x, pixels (cylindrical: pixels per radian)
  double fy = 0;               // focal length along y, pixels
  double cx = 0;               // principal point, x, pixels
  double cy = 0;               // principal point, y, pixels
  std::array<double, 8> k{};   // distortion coefficients, by model: opencv k1 k2 p1 p2 k3 k4 k5
                               // k6 (OpenCV's order); opencv-fisheye k1 k2 k3 k4;
                               // fisheye-polynomial k0..k4 (radians per pixel^n)
  double radius = 0;           // fisheye-polynomial: the image circle's radius, pixels; 0: none

  bool operator==(const lens_intrinsics&) const = default;
};

}  // namespace rtvk
