// Mirrors host/scene/camera.h: the ray through normalized image coordinates (s, t), leaving the
// lens at `lens`, a point of the unit disk.
#ifndef RTVK_CAMERA_GLSL
#define RTVK_CAMERA_GLSL
#include "ray.glsl"

ray get_ray(camera_ubo cam, float s, float t, vec2 lens) {
  vec2 rd = cam.lens_radius * lens;
  vec3 offset = cam.lens_u * rd.x + cam.lens_v * rd.y;
  return ray(cam.origin + offset,
             cam.lower_left + s * cam.horizontal + t * cam.vertical - cam.origin - offset);
}

// Mirrors pixel_coordinate in host/cpu/render_cpu.h.
float pixel_coordinate(float x, uint n) { return n > 1u ? x / float(n - 1u) : 0.5; }

#endif
