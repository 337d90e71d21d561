// Mirrors host/camera.h: the ray through normalized image coordinates (u, v).
#ifndef RTVK_CAMERA_GLSL
#define RTVK_CAMERA_GLSL
#include "ray.glsl"

ray get_ray(camera_ubo cam, float u, float v) {
  return ray(cam.origin, cam.lower_left + u * cam.horizontal + v * cam.vertical - cam.origin);
}

// Mirrors pixel_coordinate in host/render_cpu.h.
float pixel_coordinate(uint i, uint n) { return n > 1u ? float(i) / float(n - 1u) : 0.5; }

#endif
