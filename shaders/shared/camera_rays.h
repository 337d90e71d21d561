// The camera models: the ray through a point of the image, from the vectors the camera class
// precomputes (host/scene/camera.h owns the pose and computes them; the GPU reads them from the
// camera_ubo the host fills). docs/camera.md has each model's formula.
#ifndef RTVK_CAMERA_RAYS_H
#define RTVK_CAMERA_RAYS_H
#include "kernel_lang.h"
#include "random.h"
#include "ray.h"
#include "shared_types.h"

RTVK_KERNELS_BEGIN

#ifdef __cplusplus
// The camera's precomputed vectors in the compilation's `real`: the fields of camera_ubo
// (shared_types.h, what the GPU reads) that get_ray uses, by the same names.
struct camera_frame {
  real3 origin;         // eye position, scene units
  real3 horizontal;     // full viewport width as a vector, on the focus plane, scene units
  real3 vertical;       // full viewport height as a vector, on the focus plane, scene units
  real3 lower_left;     // lower-left corner of the viewport, scene units
  real3 to_lower_left;  // lower_left - origin, formed without cancelling (in double on the host)
  real3 lens_u;         // unit vector to the camera's right
  real3 lens_v;         // unit vector to the camera's up
  real3 axis_w;         // unit vector backwards, away from what the camera looks at
  real lens_radius;     // aperture / 2, scene units
  real aspect;          // image width / height
  real fisheye_fov;     // fisheye field of view across the circle, radians
  real focus_dist;      // distance to the plane in perfect focus, scene units
  uint projection;      // RTVK_PROJECTION_*
  real time_open;       // the instant the shutter opens, seconds (frame time + shutter open)
  real shutter;         // how long it stays open, seconds; 0: an instant
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

inline ray sample_ray(camera_frame cam, uint width, uint height, uint i, uint j, random_stream s,
                      bool jitter, bool lens, uint strata, uint sample_index) {
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
  r.time = cam.shutter > real(0.0) ? cam.time_open + cam.shutter * real(rnd(s, dim_time))
                                   : cam.time_open;
  return r;
}

RTVK_KERNELS_END

#endif  // RTVK_CAMERA_RAYS_H
