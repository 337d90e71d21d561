#version 460
// A ray that hit nothing: the payload keeps what the any-hit shader found (nothing), and
// render_ray.rgen shades the sky.
#extension GL_EXT_ray_tracing : require

void main() {}
