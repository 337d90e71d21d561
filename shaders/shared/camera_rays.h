// The camera models: the ray through a point of the image, from the vectors the camera class
// precomputes (host/camera/camera.h owns the pose and computes them; the GPU reads them from the
// camera_ubo the host fills). docs/camera.md has each model's formula.
#ifndef RTVK_CAMERA_RAYS_H
#define RTVK_CAMERA_RAYS_H
#include "camera_ubo.h"
#include "kernel_lang.h"
#include "random.h"
#include "ray.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// The camera's precomputed vectors in the compilation's `real`: camera_ubo's fields (camera_ubo.h,
// what the GPU reads), made from the same list, by the same names.
#define RTVK_FRAME_TYPE_vec3 real3
#define RTVK_FRAME_TYPE_vec4 real4
#define RTVK_FRAME_TYPE_float real
#define RTVK_FRAME_TYPE_uint uint
#define RTVK_CAMERA_FRAME_MEMBER(type, name) RTVK_FRAME_TYPE_##type name;
struct camera_frame {
  RTVK_CAMERA_FIELDS(RTVK_CAMERA_FRAME_MEMBER)
};
#else
#define camera_frame camera_ubo
#endif

// The direction get_ray gives at (s, t) for the equirectangular and fisheye models (no lens).
inline precise real3 panoramic_direction(camera_frame cam, real s, real t) {
  if (cam.projection == RTVK_PROJECTION_EQUIRECTANGULAR) {
    precise real phi = (s - real(0.5)) * real(2.0) * pi;  // longitude, 0 straight ahead, + right
    precise real theta = (t - real(0.5)) * pi;            // latitude, + up
    return cos(theta) * (sin(phi) * cam.lens_u - cos(phi) * cam.axis_w) + sin(theta) * cam.lens_v;
  }
  // Fisheye: a circle that touches the top and bottom edges.
  precise real x = (real(2.0) * s - real(1.0)) * cam.aspect;
  precise real y = real(2.0) * t - real(1.0);
  precise real r = sqrt(x * x + y * y);
  if (r > real(1.0)) return real3(0.0);  // outside the lens: no ray
  if (r == real(0.0)) return -cam.axis_w;
  precise real theta = cam.projection == RTVK_PROJECTION_FISHEYE_EQUIDISTANT
                           ? r * cam.fisheye_fov / real(2.0)
                           : real(2.0) * asin(r * sin(cam.fisheye_fov / real(4.0)));
  return cos(theta) * -cam.axis_w + sin(theta) * (x / r * cam.lens_u + y / r * cam.lens_v);
}

// Newton steps the calibrated models' inverses take at most (each counts against lavapipe's loop
// budget in render.comp); they converge in 3 to 6 where the host's check let the lens through.
#define RTVK_LENS_ITERATIONS 20u

// Whether the compilation meets calibrated cameras (lens models, rolling shutters): C++ always;
// each shader says. render.comp makes it a specialization constant, so that its pipelines for
// ideal cameras compile the lens models out (present but unused, they cost lavapipe 5% on
// book-final).
#ifdef __cplusplus
inline constexpr bool calibrated_cameras = true;
#endif

// Whether `projection` is one of the calibrated models, whose rays come from pixels and intrinsics.
inline bool calibrated_model(uint projection) {
  return calibrated_cameras && projection >= RTVK_PROJECTION_OPENCV;
}

// Where an inverse stops: within a few of the compilation's epsilon of the target (relative to
// its size), and where it gives up: 64 times that, the float rounding of a residual near 1.
inline precise real lens_tolerance(real target) {
  return real(16.0) * real_epsilon * (real(1.0) + target);
}

// OpenCV's rational radial-tangential distortion (cv::projectPoints) of the normalized point p
// (x / z, y / z), and its partial derivatives: d_dx = d(distorted) / dx, d_dy = ... / dy.
// ka = (k1, k2, p1, p2), kb = (k3, k4, k5, k6).
inline precise real2 opencv_distort(real4 ka, real4 kb, real2 p, OUT(real2) d_dx, OUT(real2) d_dy) {
  precise real r2 = p.x * p.x + p.y * p.y;
  precise real a = real(1.0) + r2 * (ka.x + r2 * (ka.y + r2 * kb.x));
  precise real b = real(1.0) + r2 * (kb.y + r2 * (kb.z + r2 * kb.w));
  precise real da = ka.x + r2 * (real(2.0) * ka.y + r2 * real(3.0) * kb.x);  // d a / d r2
  precise real db = kb.y + r2 * (real(2.0) * kb.z + r2 * real(3.0) * kb.w);  // d b / d r2
  precise real radial = a / b;
  precise real dradial = (da * b - a * db) / (b * b);
  precise real xy = p.x * p.y;
  precise real cross_term = real(2.0) * xy * dradial + real(2.0) * ka.z * p.x +
                            real(2.0) * ka.w * p.y;  // d xd / dy = d yd / dx
  precise real dx_dx =
      radial + real(2.0) * p.x * p.x * dradial + real(2.0) * ka.z * p.y + real(6.0) * ka.w * p.x;
  precise real dy_dy =
      radial + real(2.0) * p.y * p.y * dradial + real(6.0) * ka.z * p.y + real(2.0) * ka.w * p.x;
  d_dx = real2(dx_dx, cross_term);
  d_dy = real2(cross_term, dy_dy);
  precise real xd = p.x * radial + real(2.0) * ka.z * xy + ka.w * (r2 + real(2.0) * p.x * p.x);
  precise real yd = p.y * radial + ka.z * (r2 + real(2.0) * p.y * p.y) + real(2.0) * ka.w * xy;
  return real2(xd, yd);
}

// The normalized point p that opencv_distort takes to `target`, by Newton's method from target
// itself; false where it does not converge, the Jacobian folds, or p leaves the radius where the
// lens is invertible (r^2 <= limit2, found by the host).
inline bool opencv_undistort(real4 ka, real4 kb, real2 target, real limit2, OUT(real2) p) {
  precise real tol = lens_tolerance(max(abs(target.x), abs(target.y)));
  precise real loose = real(64.0) * tol;
  precise real2 at = target;
  bool converged = false;
  for (uint n = 0u; n <= RTVK_LENS_ITERATIONS; ++n) {
    real2 d_dx, d_dy;
    precise real2 e = opencv_distort(ka, kb, at, d_dx, d_dy) - target;
    precise real err = max(abs(e.x), abs(e.y));
    converged = err <= tol || (n == RTVK_LENS_ITERATIONS && err <= loose);
    if (converged || n == RTVK_LENS_ITERATIONS) break;
    precise real det = d_dx.x * d_dy.y - d_dy.x * d_dx.y;
    if (!(det > real(0.0))) break;  // folded
    precise real2 step = real2(d_dy.y * e.x - d_dy.x * e.y, d_dx.x * e.y - d_dx.y * e.x);
    at = at - step / det;
  }
  p = at;
  precise real r2 = at.x * at.x + at.y * at.y;
  return converged && r2 <= limit2;
}

// OpenCV's fisheye (Kannala-Brandt): the distorted angle theta_d of a ray at angle theta from the
// axis, theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8), and its derivative.
inline precise real fisheye_distort(real4 k, real theta, OUT(real) slope) {
  precise real t2 = theta * theta;
  precise real d_dtheta =
      real(1.0) + t2 * (real(3.0) * k.x +
                        t2 * (real(5.0) * k.y + t2 * (real(7.0) * k.z + t2 * real(9.0) * k.w)));
  slope = d_dtheta;
  precise real d = theta * (real(1.0) + t2 * (k.x + t2 * (k.y + t2 * (k.z + t2 * k.w))));
  return d;
}

// The angle theta in [0, theta_max] that fisheye_distort takes to theta_d, by Newton's method
// (from theta_d, as cv::fisheye::undistortPoints starts); false where it does not converge.
inline bool fisheye_undistort(real4 k, real theta_d, real theta_max, OUT(real) theta) {
  precise real tol = lens_tolerance(theta_d);
  precise real loose = real(64.0) * tol;
  precise real at = min(theta_d, theta_max);
  bool converged = false;
  for (uint n = 0u; n <= RTVK_LENS_ITERATIONS; ++n) {
    real slope;
    precise real e = fisheye_distort(k, at, slope) - theta_d;
    converged = abs(e) <= tol || (n == RTVK_LENS_ITERATIONS && abs(e) <= loose);
    if (converged || n == RTVK_LENS_ITERATIONS || !(slope > real(0.0))) break;
    precise real next = at - e / slope;
    at = min(max(next, real(0.0)), theta_max);
  }
  theta = at;
  return converged;
}

// The direction a calibrated model sees at image point (x, y), in pixels with pixel (0, 0)'s
// center at (0, 0), x to the right and y down (OpenCV's), in the camera's frame: x right, y
// down, z forward (OpenCV's). Zero where the model sees nothing: outside the fisheyes' fields,
// past a cylinder's half turn, where an inverse does not converge.
inline precise real3 calibrated_direction(camera_frame cam, real x, real y) {
  precise real2 q =
      real2((x - cam.intrinsics.z) / cam.intrinsics.x, (y - cam.intrinsics.w) / cam.intrinsics.y);
  if (cam.projection == RTVK_PROJECTION_OPENCV) {
    real2 p;
    if (!opencv_undistort(cam.distortion_a, cam.distortion_b, q, cam.lens_limit, p))
      return real3(0.0);
    return real3(p.x, p.y, real(1.0));
  }
  if (cam.projection == RTVK_PROJECTION_CYLINDRICAL) {
    if (abs(q.x) > pi) return real3(0.0);  // q.x: longitude, radians
    return real3(sin(q.x), q.y, cos(q.x));
  }
  // The fisheyes: an angle from the axis, about the direction of q.
  precise real r = sqrt(q.x * q.x + q.y * q.y);
  precise real theta;
  if (cam.projection == RTVK_PROJECTION_OPENCV_FISHEYE) {
    if (r > cam.lens_limit) return real3(0.0);  // r: the distorted angle
    if (!fisheye_undistort(cam.distortion_a, r, cam.lens_angle, theta)) return real3(0.0);
  } else {  // fisheye-polynomial: r in the calibration's pixels (intrinsics.xy: the scale)
    if (cam.lens_limit > real(0.0) && r > cam.lens_limit) return real3(0.0);
    real4 k = cam.distortion_a;
    theta = k.x + r * (k.y + r * (k.z + r * (k.w + r * cam.distortion_b.x)));
    if (theta < real(0.0) || theta > pi) return real3(0.0);
  }
  if (r == real(0.0)) return real3(sin(theta), real(0.0), cos(theta));
  precise real sin_theta = sin(theta);
  precise real3 d = real3(sin_theta * q.x / r, sin_theta * q.y / r, cos(theta));
  return d;
}

// The world ray of a calibrated model through image point (x, y) (calibrated_direction's
// pixels); the camera frame's x is lens_u, y is -lens_v, z is -axis_w.
inline ray calibrated_ray(camera_frame cam, real x, real y) {
  precise real3 c = calibrated_direction(cam, x, y);
  precise real3 direction = c.x * cam.lens_u - c.y * cam.lens_v - c.z * cam.axis_w;
  return ray(cam.origin, direction, real(0.0));
}

// The ray through normalized image coordinates (s, t) -- (0, 0) is the lower-left corner of the
// viewport, (1, 1) the upper-right -- leaving the lens at `lens`, a point of the unit disk. Where
// the model sees nothing (outside a fisheye's circle) the direction is zero: no ray, and the
// renderers draw the pixel black.
inline ray get_ray(camera_frame cam, real s, real t, real2 lens) {
  precise real2 rd = cam.lens_radius * lens;
  precise real3 offset = cam.lens_u * rd.x + cam.lens_v * rd.y;
  if (cam.projection == RTVK_PROJECTION_PERSPECTIVE) {
    precise real3 origin = cam.origin + offset;
    // From the eye, not from the scene's origin: lower_left - origin computed in float would
    // cancel away the direction's low bits for a camera far from the origin.
    precise real3 direction = cam.to_lower_left + s * cam.horizontal + t * cam.vertical - offset;
    return ray(origin, direction, real(0.0));
  }
  if (cam.projection == RTVK_PROJECTION_ORTHOGRAPHIC) {
    precise real3 on_focus_plane = cam.lower_left + s * cam.horizontal + t * cam.vertical;
    precise real3 from = on_focus_plane + cam.focus_dist * cam.axis_w + offset;
    precise real3 direction = on_focus_plane - from;
    return ray(from, direction, real(0.0));
  }
  if (calibrated_model(cam.projection)) {  // (s, t) = (0, 0): the image's lower-left corner
    precise real x = s * real(cam.image_width) - real(0.5);
    precise real y = (real(1.0) - t) * real(cam.image_height) - real(0.5);
    return calibrated_ray(cam, x, y);
  }
  return ray(cam.origin, panoramic_direction(cam, s, t), real(0.0));
}

// Normalized coordinate of position x along a side of n pixels: x / (n - 1), as the lesson does,
// and the side's center when n == 1 (where the lesson would divide by zero).
inline precise real pixel_coordinate(real x, uint n) {
  return n > 1u ? x / real(n - 1u) : real(0.5);
}

// The first ray of one sample of pixel (i, j) of a width x height image, j counted from the
// bottom as the lesson does: through a random spot of the pixel when `jitter`, else its corner,
// and through a random point of the lens when `lens` and the camera has an aperture, at an
// instant drawn uniformly while the shutter is open. `s` is the sample's stream
// (pixel_sample_stream). Stratified (the third book's final chapter) when strata > 1: the pixel
// is cut into strata x strata cells, and sample k < strata^2 jitters inside one of them, each
// cell once. The book visits the cells row by row; here sample k = j strata + i takes column i
// and row (i + j) mod strata, so that each run of strata samples from a multiple of strata also
// covers every row and column once (a partial render, the viewer's first frames, is not squeezed
// into the bottom rows). A sample's spot depends on its index alone: sample ranges drawn apart
// still merge into the whole render.
inline precise real2 pixel_spot(random_stream s, uint strata, uint sample_index) {
  precise real2 spot = real2(real(rnd(s, dim_jitter_u)), real(rnd(s, dim_jitter_v)));
  if (strata <= 1u || sample_index >= strata * strata) return spot;
  uint column = sample_index % strata;
  uint row = (column + sample_index / strata) % strata;
  precise real2 cell = real2(real(column), real(row));
  return (cell + spot) / real(strata);
}

// A rolling shutter opens row y (from the top) |readout| * y / (height - 1) seconds after the
// first row, top row first for readout > 0, bottom row first for < 0.
inline precise real row_delay(camera_frame cam, uint height, uint j) {
  if (!calibrated_cameras || cam.readout == real(0.0) || height < 2u) return real(0.0);
  uint rows_before = cam.readout > real(0.0) ? height - 1u - j : j;
  return abs(cam.readout) * real(rows_before) / real(height - 1u);
}

// The instant a sample sees: its row's opening plus a uniform share of the time it stays open.
inline precise real sample_time(camera_frame cam, uint height, uint j, random_stream s) {
  precise real open = cam.time_open + row_delay(cam, height, j);
  return cam.shutter > real(0.0) ? open + cam.shutter * real(rnd(s, dim_time)) : open;
}

inline ray sample_ray(camera_frame cam, uint width, uint height, uint i, uint j, random_stream s,
                      bool jitter, bool lens, uint strata, uint sample_index) {
  if (calibrated_model(cam.projection)) {  // pixel (i, row from the top)'s center is (i, row)
    precise real2 spot = jitter ? pixel_spot(s, strata, sample_index) : real2(0.5);
    precise real x = real(i) + spot.x - real(0.5);
    precise real y = real(height - 1u - j) + real(0.5) - spot.y;
    ray r = calibrated_ray(cam, x, y);
    r.time = sample_time(cam, height, j, s);
    return r;
  }
  precise real2 spot = jitter ? pixel_spot(s, strata, sample_index) : real2(0.0);
  precise real x = real(i) + spot.x;
  precise real y = real(j) + spot.y;
  precise real u = pixel_coordinate(x, width);
  precise real v = pixel_coordinate(y, height);
  precise real2 on_lens =
      lens && cam.lens_radius > real(0.0)
          ? random_in_unit_disk(real(rnd(s, dim_lens_a)), real(rnd(s, dim_lens_b)))
          : real2(0.0);
  ray r = get_ray(cam, u, v, on_lens);
  r.time = sample_time(cam, height, j, s);
  return r;
}

// The ray the ground truth of pixel (i, j) (aov.h) is measured along, j from the bottom: through
// the pixel's center for the calibrated models (where OpenCV puts pixel (i, row)), through the
// lesson's unjittered spot for the ideal ones, through the lens's center, in the middle of the
// row's exposure.
inline ray center_ray(camera_frame cam, uint width, uint height, uint i, uint j) {
  ray r;
  if (calibrated_model(cam.projection)) {
    r = calibrated_ray(cam, real(i), real(height - 1u - j));
  } else {
    precise real u = pixel_coordinate(real(i), width);
    precise real v = pixel_coordinate(real(j), height);
    r = get_ray(cam, u, v, real2(0.0));
  }
  precise real middle = cam.time_open + row_delay(cam, height, j) + cam.shutter * real(0.5);
  r.time = middle;
  return r;
}

RTVK_KERNELS_END

#endif  // RTVK_CAMERA_RAYS_H
