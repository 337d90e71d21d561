#pragma once
// An independent float64 transcription of the lesson's program (its own vec3 class, sphere,
// hittable list, camera and main loop), sharing no code with rtvk. The tests hold rtvk's output
// to this, byte for byte. The one addition is the guard for a one-pixel side, which the lesson
// leaves as a division by zero; rtvk uses the side's center there.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace lesson {

struct vec3 {
  double e[3];
  vec3() : e{0, 0, 0} {}
  vec3(double e0, double e1, double e2) : e{e0, e1, e2} {}
  double x() const { return e[0]; }
  double y() const { return e[1]; }
  double z() const { return e[2]; }
  vec3 operator-() const { return vec3(-e[0], -e[1], -e[2]); }
  double length_squared() const { return e[0] * e[0] + e[1] * e[1] + e[2] * e[2]; }
  double length() const { return std::sqrt(length_squared()); }
};
inline vec3 operator+(const vec3& u, const vec3& v) {
  return vec3(u.e[0] + v.e[0], u.e[1] + v.e[1], u.e[2] + v.e[2]);
}
inline vec3 operator-(const vec3& u, const vec3& v) {
  return vec3(u.e[0] - v.e[0], u.e[1] - v.e[1], u.e[2] - v.e[2]);
}
inline vec3 operator*(double t, const vec3& v) {
  return vec3(t * v.e[0], t * v.e[1], t * v.e[2]);
}
inline vec3 operator/(vec3 v, double t) {
  return (1 / t) * v;
}
inline double dot(const vec3& u, const vec3& v) {
  return u.e[0] * v.e[0] + u.e[1] * v.e[1] + u.e[2] * v.e[2];
}
inline vec3 unit_vector(vec3 v) {
  return v / v.length();
}

struct ray {
  vec3 orig, dir;
  vec3 at(double t) const { return orig + t * dir; }
};

struct hit_record {
  vec3 p, normal;
  double t = 0;
};

struct sphere {
  vec3 center;
  double radius;
  bool hit(const ray& r, double t_min, double t_max, hit_record& rec) const {
    vec3 oc = r.orig - center;
    auto a = r.dir.length_squared();
    auto half_b = dot(oc, r.dir);
    auto c = oc.length_squared() - radius * radius;
    auto discriminant = half_b * half_b - a * c;
    if (discriminant < 0) return false;
    auto sqrtd = std::sqrt(discriminant);
    auto root = (-half_b - sqrtd) / a;
    if (root < t_min || t_max < root) {
      root = (-half_b + sqrtd) / a;
      if (root < t_min || t_max < root) return false;
    }
    rec.t = root;
    rec.p = r.at(rec.t);
    vec3 outward_normal = (rec.p - center) / radius;
    bool front_face = dot(r.dir, outward_normal) < 0;
    rec.normal = front_face ? outward_normal : -outward_normal;
    return true;
  }
};

inline bool hit_world(const std::vector<sphere>& world, const ray& r, double t_min, double t_max,
                      hit_record& rec) {
  hit_record temp_rec;
  bool hit_anything = false;
  auto closest_so_far = t_max;
  for (const auto& object : world) {
    if (object.hit(r, t_min, closest_so_far, temp_rec)) {
      hit_anything = true;
      closest_so_far = temp_rec.t;
      rec = temp_rec;
    }
  }
  return hit_anything;
}

inline vec3 ray_color(const ray& r, const std::vector<sphere>& world) {
  hit_record rec;
  if (hit_world(world, r, 0, std::numeric_limits<double>::infinity(), rec))
    return 0.5 * (rec.normal + vec3(1, 1, 1));
  vec3 unit_direction = unit_vector(r.dir);
  auto t = 0.5 * (unit_direction.y() + 1.0);
  return (1.0 - t) * vec3(1.0, 1.0, 1.0) + t * vec3(0.5, 0.7, 1.0);
}

// The lesson's main(): the seed world seen by the lesson's camera, written as P3.
inline std::string render_seed_p3(double aspect_ratio, int image_width) {
  const int image_height = std::max(1, static_cast<int>(image_width / aspect_ratio));
  const std::vector<sphere> world{{vec3(0, 0, -1), 0.5}, {vec3(0, -100.5, -1), 100}};

  auto viewport_height = 2.0;
  auto viewport_width = aspect_ratio * viewport_height;
  auto focal_length = 1.0;
  auto origin = vec3(0, 0, 0);
  auto horizontal = vec3(viewport_width, 0, 0);
  auto vertical = vec3(0, viewport_height, 0);
  auto lower_left_corner = origin - horizontal / 2 - vertical / 2 - vec3(0, 0, focal_length);

  std::ostringstream out;
  out << "P3\n" << image_width << ' ' << image_height << "\n255\n";
  for (int j = image_height - 1; j >= 0; --j) {
    for (int i = 0; i < image_width; ++i) {
      auto u = image_width > 1 ? double(i) / (image_width - 1) : 0.5;
      auto v = image_height > 1 ? double(j) / (image_height - 1) : 0.5;
      ray r{origin, lower_left_corner + u * horizontal + v * vertical - origin};
      vec3 c = ray_color(r, world);
      out << static_cast<int>(255.999 * c.x()) << ' ' << static_cast<int>(255.999 * c.y()) << ' '
          << static_cast<int>(255.999 * c.z()) << '\n';
    }
  }
  return out.str();
}

}  // namespace lesson
