// Mirrors host/base/ray.h and host/cpu/hittable.h.
#ifndef RTVK_RAY_GLSL
#define RTVK_RAY_GLSL

const float pi = 3.1415926535897932385;

struct ray {
  precise vec3 origin;     // where the ray starts, scene units
  precise vec3 direction;  // not normalized
};

// glm's dot and length, operation for operation: (x * x' + y * y') + z * z', no fused
// multiply-adds (GLSL's built-ins leave the order and the fusing to the device).
precise float dot3(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
precise float length3(vec3 v) { return sqrt(dot3(v, v)); }

precise vec3 ray_at(ray r, float t) { return r.origin + t * r.direction; }

struct hit_record {
  precise vec3 p;           // where the ray hit
  precise vec3 normal;      // unit normal facing against the ray
  precise float t;          // ray parameter of the hit
  bool front_face;  // the ray arrived from outside
  uint material;    // index into the materials buffer
  precise float offset;     // how far a ray leaving p starts off the surface
};

// Mirrors hit_record::scatter_origin: lifted off the surface to the side the ray leaves to.
precise vec3 scatter_origin(hit_record rec, vec3 direction) {
  precise float facing = dot3(direction, rec.normal);
  return rec.p + (facing >= 0.0 ? rec.offset : -rec.offset) * rec.normal;
}

// The lesson divides as (1/t) * v; the shader does the same to stay close to the reference.
precise vec3 divide(vec3 v, float t) { return (1.0 / t) * v; }
precise vec3 unit_vector(vec3 v) { return divide(v, length3(v)); }

void set_face_normal(precise inout hit_record rec, ray r, vec3 outward_normal) {
  precise float facing = dot3(r.direction, outward_normal);
  rec.front_face = facing < 0.0;
  rec.normal = rec.front_face ? outward_normal : -outward_normal;
}

#endif
