// The scene file's validator: each reader names the field it reads (its JSON pointer) and says
// what it expected in every refusal.
#include "scene_file_fields.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "format.h"

namespace rtvk::scene_json {

void scene_reader::fail(const std::string& path, const std::string& what) const {
  throw usage_error(file_ + ": " + (path.empty() ? "/" : path) + ": " + what);
}

void scene_reader::only_fields(const json& obj, const std::string& path,
                               const std::set<std::string>& allowed) const {
  if (!obj.is_object()) fail(path, "expected an object, got " + type_of(obj));
  for (const auto& [key, value] : obj.items())
    if (!allowed.count(key)) fail(path + "/" + key, "unknown field");
}

const json& scene_reader::required(const json& obj, const std::string& path,
                                   const std::string& key) const {
  if (!obj.contains(key)) fail(path, "missing field \"" + key + "\"");
  return obj[key];
}

double scene_reader::number(const json& j, const std::string& path) const {
  if (!j.is_number()) fail(path, "expected a number, got " + type_of(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "expected a finite number, got " + format_number(v));
  return v;
}

double scene_reader::number_in(const json& j, const std::string& path, double lo, double hi) const {
  const double v = number(j, path);
  if (v < lo || v > hi)
    fail(path, "expected a number in [" + format_number(lo) + ", " + format_number(hi) + "], got " +
                   format_number(v));
  return v;
}

long long scene_reader::integer(const json& j, const std::string& path, long long lo,
                                long long hi) const {
  if (!j.is_number_integer())
    fail(path, "expected an integer, got " + (j.is_number() ? j.dump() : type_of(j)));
  const long long v = j.is_number_unsigned()
                          ? (long long)std::min<std::uint64_t>(j.get<std::uint64_t>(), 1ull << 62)
                          : j.get<long long>();
  if (v < lo || v > hi)
    fail(path, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                   "], got " + j.dump());
  return v;
}

vec3 scene_reader::vector3(const json& j, const std::string& path) const {
  if (!j.is_array() || j.size() != 3)
    fail(path, "expected an array of 3 numbers, got " + type_of(j));
  return vec3(number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2"));
}

color scene_reader::albedo(const json& j, const std::string& path) const {
  const vec3 c = vector3(j, path);
  for (int k = 0; k < 3; ++k)
    if (c[k] < 0 || c[k] > 1)
      fail(path + "/" + std::to_string(k),
           "expected an albedo in [0, 1], got " + format_number(c[k]));
  return c;
}

color scene_reader::radiance(const json& j, const std::string& path) const {
  const vec3 c = vector3(j, path);
  for (int k = 0; k < 3; ++k)
    if (c[k] < 0)
      fail(path + "/" + std::to_string(k), "expected a color >= 0, got " + format_number(c[k]));
  return c;
}

bool scene_reader::flag(const json& j, const std::string& p, const char* key) const {
  if (!j.contains(key)) return false;
  if (!j[key].is_boolean()) fail(p + "/" + key, "expected true or false, got " + type_of(j[key]));
  return j[key].get<bool>();
}

int scene_reader::material_named(const json& j, const std::string& p) const {
  const json& m = required(j, p, "material");
  if (!m.is_string()) fail(p + "/material", "expected a material name, got " + type_of(m));
  const auto found = material_index.find(m.get<std::string>());
  if (found == material_index.end())
    fail(p + "/material", "no material named \"" + m.get<std::string>() + "\" in /materials");
  return found->second;
}

std::string scene_reader::type_of(const json& j) {
  if (j.is_number()) return "a number";
  return std::string(j.is_array() || j.is_object() ? "an " : "a ") + j.type_name();
}

std::string escape_pointer(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

json vec_json(const vec3& v) {
  return json::array({v.x, v.y, v.z});
}

}  // namespace rtvk::scene_json
