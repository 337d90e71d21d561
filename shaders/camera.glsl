// Mirrors host/scene/camera.h: the ray through normalized image coordinates (s, t), leaving the
// lens at `lens`, a point of the unit disk.
#ifndef RTVK_CAMERA_GLSL
#define RTVK_CAMERA_GLSL
#include "ray.glsl"



// Mirrors camera::panoramic_direction: the equirectangular and fisheye models.
precise vec3 panoramic_direction(camera_ubo cam, float s, float t) {
  if (cam.projection == RTVK_PROJECTION_EQUIRECTANGULAR) {
    precise float phi = (s - 0.5) * 2.0 * pi;  // longitude, 0 straight ahead, + to the right
    precise float theta = (t - 0.5) * pi;      // latitude, + up
    return cos(theta) * (sin(phi) * cam.lens_u - cos(phi) * cam.axis_w) + sin(theta) * cam.lens_v;
  }
  // Fisheye: a circle that touches the top and bottom edges.
  precise float x = (2.0 * s - 1.0) * cam.aspect;
  precise float y = 2.0 * t - 1.0;
  precise float r = sqrt(x * x + y * y);
  if (r > 1.0) return vec3(0.0);  // outside the lens: no ray
  if (r == 0.0) return -cam.axis_w;
  precise float theta = cam.projection == RTVK_PROJECTION_FISHEYE_EQUIDISTANT
                            ? r * cam.fisheye_fov / 2.0
                            : 2.0 * asin(r * sin(cam.fisheye_fov / 4.0));
  return cos(theta) * -cam.axis_w + sin(theta) * (x / r * cam.lens_u + y / r * cam.lens_v);
}

// Where the model sees nothing (outside a fisheye's circle) the direction is zero: no ray.
ray get_ray(camera_ubo cam, float s, float t, vec2 lens) {
  precise vec2 rd = cam.lens_radius * lens;
  precise vec3 offset = cam.lens_u * rd.x + cam.lens_v * rd.y;
  if (cam.projection == RTVK_PROJECTION_PERSPECTIVE) {
    precise vec3 origin = cam.origin + offset;
    precise vec3 direction =
        cam.lower_left + s * cam.horizontal + t * cam.vertical - cam.origin - offset;
    return ray(origin, direction);
  }
  if (cam.projection == RTVK_PROJECTION_ORTHOGRAPHIC) {
    precise vec3 on_focus_plane = cam.lower_left + s * cam.horizontal + t * cam.vertical;
    precise vec3 from = on_focus_plane + cam.focus_dist * cam.axis_w + offset;
    precise vec3 direction = on_focus_plane - from;
    return ray(from, direction);
  }
  return ray(cam.origin, panoramic_direction(cam, s, t));
}

// Mirrors pixel_coordinate in host/cpu/render_cpu.h.
precise float pixel_coordinate(float x, uint n) { return n > 1u ? x / float(n - 1u) : 0.5; }

#endif
