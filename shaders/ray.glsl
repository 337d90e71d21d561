// Mirrors host/base/ray.h and host/cpu/hittable.h.
#ifndef RTVK_RAY_GLSL
#define RTVK_RAY_GLSL

struct ray {
  vec3 origin;     // where the ray starts, scene units
  vec3 direction;  // not normalized
};

vec3 ray_at(ray r, float t) { return r.origin + t * r.direction; }

struct hit_record {
  vec3 p;           // where the ray hit
  vec3 normal;      // unit normal facing against the ray
  float t;          // ray parameter of the hit
  bool front_face;  // the ray arrived from outside
  uint material;    // index into the materials buffer
  float offset;     // how far a ray leaving p starts off the surface
};

// Mirrors hit_record::scatter_origin: lifted off the surface to the side the ray leaves to.
vec3 scatter_origin(hit_record rec, vec3 direction) {
  return rec.p + (dot(direction, rec.normal) >= 0.0 ? rec.offset : -rec.offset) * rec.normal;
}

// The lesson divides as (1/t) * v; the shader does the same to stay close to the reference.
vec3 divide(vec3 v, float t) { return (1.0 / t) * v; }
vec3 unit_vector(vec3 v) { return divide(v, length(v)); }

void set_face_normal(inout hit_record rec, ray r, vec3 outward_normal) {
  rec.front_face = dot(r.direction, outward_normal) < 0.0;
  rec.normal = rec.front_face ? outward_normal : -outward_normal;
}

#endif
