// Mirrors host/scene/camera.h: the ray through normalized image coordinates (s, t), leaving the
// lens at `lens`, a point of the unit disk.
#ifndef RTVK_CAMERA_GLSL
#define RTVK_CAMERA_GLSL
#include "ray.glsl"

ray get_ray(camera_ubo cam, float s, float t, vec2 lens) {
  precise vec2 rd = cam.lens_radius * lens;
  precise vec3 offset = cam.lens_u * rd.x + cam.lens_v * rd.y;
  precise vec3 origin = cam.origin + offset;
  precise vec3 direction =
      cam.lower_left + s * cam.horizontal + t * cam.vertical - cam.origin - offset;
  return ray(origin, direction);
}

// Mirrors pixel_coordinate in host/cpu/render_cpu.h.
precise float pixel_coordinate(float x, uint n) { return n > 1u ? x / float(n - 1u) : 0.5; }

#endif
