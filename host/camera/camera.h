#pragma once
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>

#include "camera_rays.h"
#include "image_size.h"
#include "lens_intrinsics.h"
#include "vec3.h"

namespace rtvk {

// How directions map onto the image (docs/camera.md has each model's formula and a picture).
enum class projection {
  perspective,          // the lesson's pinhole (and thin lens) camera
  orthographic,         // parallel rays along -w from the perspective viewport on the focus plane
  equirectangular,      // the full sphere: longitude across, latitude up (2:1 for square pixels)
  fisheye_equidistant,  // a round image; the angle from the axis grows with the radius
  fisheye_equisolid,    // a round image of equal solid angle per area
  opencv,               // OpenCV's pinhole with radial-tangential (rational) distortion
  opencv_fisheye,       // OpenCV's fisheye (Kannala-Brandt): distorted angle k1..k4
  fisheye_polynomial,   // angle from the axis a polynomial of the image radius (f-theta lenses)
  cylindrical,          // a central cylindrical panorama: longitude across, tan(latitude) up
};

// The models a calibration sets up (lens_intrinsics): pixels, not a field of view, fix the rays.
constexpr bool is_calibrated(projection p) {
  return p == projection::opencv || p == projection::opencv_fisheye ||
         p == projection::fisheye_polynomial || p == projection::cylindrical;
}

// "perspective", "orthographic", "equirectangular", "fisheye-equidistant", "fisheye-equisolid".
std::string_view projection_name(projection p);
std::optional<projection> projection_from_name(std::string_view name);
std::string projection_names();  // all of them, comma-separated, for messages and --help

// Perspective and orthographic cameras have a thin lens (aperture, focus distance); the
// panoramic models do not, so their aperture must be 0.
constexpr bool has_lens(projection p) {
  return p == projection::perspective || p == projection::orthographic;
}

// Where the camera stands and how its lens is set. The defaults are the lesson's pinhole camera:
// at the origin, looking down -z, 90 degrees vertical field of view, everything in focus.
struct camera_pose {
  point3 lookfrom{0, 0, 0};  // eye position, scene units
  point3 lookat{0, 0, -1};   // point the camera looks at, scene units
  vec3 vup{0, 1, 0};         // which way is up (need not be perpendicular to the view)
  double vfov = 90;          // vertical field of view, degrees, in (0, 180)
  double aperture = 0;       // lens diameter, scene units; 0 is a pinhole
  double focus_dist = 1;     // distance to the plane in perfect focus, scene units, > 0
  rtvk::projection projection = rtvk::projection::perspective;  // how directions map to pixels
  double fisheye_fov = 180;  // the fisheye models' field of view across the circle, degrees
  double shutter_open = 0;   // when the shutter opens, seconds after the frame's time
  double shutter_close = 0;  // when it closes, seconds after the frame's time, >= shutter_open;
                             // equal: an instant, no motion blur
  double readout = 0;        // rolling shutter: seconds from the first row's opening to the
                             // last's; > 0 top row first, < 0 bottom row first, 0: global
  lens_intrinsics intrinsics{};  // the calibrated models' focal lengths, principal point, distortion

  bool operator==(const camera_pose&) const = default;
};

// Everything a ray needs is precomputed once, as in the lesson, so get_ray is a few multiply-adds.
// A pose and a thin lens fold into the same four vectors plus the lens basis and radius.
class camera {
 public:
  // The lesson's camera. Throws std::invalid_argument for an aspect ratio that is not finite and
  // positive, a width outside [1, max_image_side], or a derived height above max_image_side.
  explicit camera(double aspect_ratio = 16.0 / 9.0, int image_width = 400)
      : camera(camera_pose{}, aspect_ratio, image_width) {}

  // A posed camera with a thin lens, for the frame at `frame_time` seconds (its shutter is open
  // from frame_time + pose.shutter_open to frame_time + pose.shutter_close); also throws
  // std::invalid_argument for a pose that does not define a view (lookfrom == lookat, vup
  // parallel to the view, vfov outside (0, 180), a fisheye field of view outside (0, 360], an
  // aperture with a model that has no lens, a shutter that closes before it opens, ...).
  camera(const camera_pose& pose, double aspect_ratio, int image_width, double frame_time = 0);

  // The ray through normalized image coordinates (s, t) -- (0, 0) is the lower-left corner of
  // the viewport, (1, 1) the upper-right -- leaving the lens at `lens`, a point of the unit disk.
  // Where the model sees nothing (outside a fisheye's circle) the direction is zero: no ray,
  // and the renderers draw the pixel black. The shared kernels' get_ray (camera_rays.h), which
  // the GPU compiles too, on this camera's vectors.
  ray get_ray(double s, double t, glm::dvec2 lens = {0, 0}) const {
    return rtvk::get_ray(frame_, s, t, lens);
  }

  // A calibrated model's ray through image point (x, y): pixels, x to the right, y down, pixel
  // (0, 0)'s center at (0, 0), as OpenCV counts them. Zero direction where it sees nothing.
  ray pixel_ray(double x, double y) const { return rtvk::calibrated_ray(frame_, x, y); }

  // Where a calibrated model images world point p, in pixel_ray's pixels (the lens's forward
  // projection, as cv::projectPoints computes it for the OpenCV models); nothing where p is
  // outside the model's field. Only for the calibrated models.
  std::optional<glm::dvec2> project(const point3& p) const;

  // The direction get_ray gives at (s, t) for the equirectangular and fisheye models (no lens).
  vec3 panoramic_direction(double s, double t) const {
    return rtvk::panoramic_direction(frame_, s, t);
  }
  // The precomputed vectors get_ray uses; the GPU's camera_ubo holds them in float.
  const camera_frame& frame() const { return frame_; }
  double aspect_ratio() const { return frame_.aspect; }
  int image_width() const { return image_width_; }
  int image_height() const { return image_height_; }
  const point3& origin() const { return frame_.origin; }
  const vec3& horizontal() const { return frame_.horizontal; }
  const vec3& vertical() const { return frame_.vertical; }
  const point3& lower_left() const { return frame_.lower_left; }
  const vec3& lens_u() const { return frame_.lens_u; }
  const vec3& lens_v() const { return frame_.lens_v; }
  double lens_radius() const { return frame_.lens_radius; }
  rtvk::projection projection() const { return rtvk::projection(frame_.projection); }
  const vec3& axis_w() const { return frame_.axis_w; }
  double focus_dist() const { return frame_.focus_dist; }
  double fisheye_fov() const { return frame_.fisheye_fov; }                // radians
  double time_open() const { return frame_.time_open; }                    // seconds
  // The last instant a sample sees: the last row's closing, under a rolling shutter. Seconds.
  double time_close() const {
    return frame_.time_open + std::abs(frame_.readout) + frame_.shutter;
  }

 private:
  int image_width_;     // pixels
  int image_height_;    // pixels, max(1, int(width / aspect))
  camera_frame frame_;  // the pose and lens as get_ray's vectors (aspect: width / height)
};

}  // namespace rtvk
