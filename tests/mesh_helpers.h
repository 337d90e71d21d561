#pragma once
// Meshes the tests make themselves, and the same mesh written as Wavefront OBJ and as glTF.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "scene.h"

namespace rtvk::test {

struct indexed_mesh {
  std::vector<point3> positions;                    // scene units
  std::vector<std::array<std::uint32_t, 3>> faces;  // counter-clockwise from outside
};

// A closed, sphere-like mesh: a cube's six faces cut into n x n squares of two triangles each,
// every vertex pushed out to radius `radius` and rounded to a multiple of 1/64 (so that every
// coordinate is exact in float and in any decimal writer). Neighboring faces share vertices.
inline indexed_mesh cube_sphere(int n, double radius = 1.0) {
  indexed_mesh m;
  std::map<std::array<int, 3>, std::uint32_t> index;  // grid point -> vertex
  const auto vertex = [&](std::array<int, 3> g) {
    const auto found = index.find(g);
    if (found != index.end()) return found->second;
    const vec3 v = glm::normalize(vec3(g[0], g[1], g[2]) / double(n) - 1.0);
    const point3 p = glm::round(64.0 * radius * v) / 64.0;
    m.positions.push_back(p);
    return index[g] = std::uint32_t(m.positions.size() - 1);
  };
  // Each face: a fixed axis at 0 or 2n, the other two running over the grid.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int a = (axis + 1) % 3, b = (axis + 2) % 3;
          const auto at = [&](int di, int dj) {
            std::array<int, 3> g{};
            g[std::size_t(axis)] = side * 2 * n;
            g[std::size_t(a)] = 2 * (i + di);
            g[std::size_t(b)] = 2 * (j + dj);
            return vertex(g);
          };
          const std::uint32_t p00 = at(0, 0), p10 = at(1, 0), p11 = at(1, 1), p01 = at(0, 1);
          // Counter-clockwise seen from outside: a x b points along +axis.
          if (side == 1) {
            m.faces.push_back({p00, p10, p11});
            m.faces.push_back({p00, p11, p01});
          } else {
            m.faces.push_back({p00, p11, p10});
            m.faces.push_back({p00, p01, p11});
          }
        }
  return m;
}

// A (2, 3) torus knot tube of about `triangles` triangles, as scripts/make-mesh.py makes it
// (without its normals): a closed, non-convex mesh that hides parts of itself, for benchmarks.
inline indexed_mesh torus_knot(std::size_t triangles) {
  const int around = std::max(8, int(std::lround(std::sqrt(double(triangles) / 16))));
  const int along = std::max(24, int(std::lround(double(triangles) / 2 / around)));
  const auto curve = [](double t) {
    const double r = 2 + std::cos(3 * t);
    return point3(r * std::cos(2 * t), r * std::sin(2 * t), -std::sin(3 * t));
  };
  indexed_mesh m;
  for (int i = 0; i < along; ++i) {
    const double t = 2 * M_PI * i / along;
    const point3 p = curve(t);
    const vec3 tangent = glm::normalize(curve(t + 1e-4) - p);
    const vec3 side = glm::normalize(glm::cross(tangent, vec3(0, 0, 1)));
    const vec3 up = glm::cross(side, tangent);
    for (int j = 0; j < around; ++j) {
      const double a = 2 * M_PI * j / around;
      m.positions.push_back(p + 0.45 * (std::cos(a) * side + std::sin(a) * up));
    }
  }
  const auto at = [&](int i, int j) { return std::uint32_t((i % along) * around + j % around); };
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < around; ++j) {
      m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

inline std::string obj_text(const indexed_mesh& m) {
  std::string out = "# rtvk test mesh\n";
  char line[160];
  for (const point3& p : m.positions) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const auto& f : m.faces) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", f[0] + 1, f[1] + 1, f[2] + 1);
    out += line;
  }
  return out;
}

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16 |
                            std::uint32_t(std::uint8_t(bytes[i + 1])) << 8 |
                            std::uint8_t(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += digits[(v >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// The mesh's binary buffer: float positions, then uint32 indices.
inline std::string gltf_buffer(const indexed_mesh& m) {
  std::string bin;
  for (const point3& p : m.positions)
    for (int k = 0; k < 3; ++k) {
      const float f = float(p[k]);
      bin.append(reinterpret_cast<const char*>(&f), 4);
    }
  for (const auto& f : m.faces)
    for (std::uint32_t v : f) bin.append(reinterpret_cast<const char*>(&v), 4);
  return bin;
}

// A glTF document of the mesh, one node placing it by `matrix` (column-major, 16 numbers; empty:
// none), its buffer at `uri` (a data: URI when empty) of `buffer_bytes` bytes.
inline std::string gltf_json(const indexed_mesh& m, const std::string& uri = "",
                             const std::string& matrix = "") {
  const std::size_t pos_bytes = m.positions.size() * 12, idx_bytes = m.faces.size() * 12;
  point3 lo(1e30), hi(-1e30);
  for (const point3& p : m.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const std::string data =
      uri.empty() ? "data:application/octet-stream;base64," + base64(gltf_buffer(m)) : uri;
  char bounds[256];
  std::snprintf(bounds, sizeof bounds, "\"min\":[%.17g,%.17g,%.17g],\"max\":[%.17g,%.17g,%.17g]",
                lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  return std::string("{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],") +
         "\"nodes\":[{\"mesh\":0" + (matrix.empty() ? "" : ",\"matrix\":[" + matrix + "]") + "}]," +
         "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}]," +
         "\"buffers\":[{\"uri\":\"" + data +
         "\",\"byteLength\":" + std::to_string(pos_bytes + idx_bytes) + "}]," +
         "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" +
         std::to_string(pos_bytes) + "},{\"buffer\":0,\"byteOffset\":" + std::to_string(pos_bytes) +
         ",\"byteLength\":" + std::to_string(idx_bytes) + "}]," +
         "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":" +
         std::to_string(m.positions.size()) + ",\"type\":\"VEC3\"," + bounds + "}," +
         "{\"bufferView\":1,\"componentType\":5125,\"count\":" +
         std::to_string(3 * m.faces.size()) + ",\"type\":\"SCALAR\"}]}";
}

// A .glb of a JSON document and its BIN chunk (the buffer without uri).
inline std::string glb_of(std::string json, std::string bin) {
  while (json.size() % 4) json += ' ';
  while (bin.size() % 4) bin += '\0';
  std::string out;
  const auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
  u32(std::uint32_t(json.size()));
  u32(0x4E4F534A);  // "JSON"
  out += json;
  u32(std::uint32_t(bin.size()));
  u32(0x004E4942);  // "BIN\0"
  out += bin;
  return out;
}

// A .glb: the JSON chunk (its buffer the BIN chunk) and the BIN chunk.
inline std::string glb_bytes(const indexed_mesh& m) {
  std::string json = gltf_json(m, "x");
  // The BIN chunk's buffer has no uri.
  const std::string with_uri = "{\"uri\":\"x\",";
  json.replace(json.find(with_uri), with_uri.size(), "{");
  return glb_of(json, gltf_buffer(m));
}

// The mesh's faces as scene triangles of material `material`.
inline void add_triangles(scene& s, const indexed_mesh& m, int material) {
  for (const auto& f : m.faces)
    s.triangles.push_back({{m.positions[f[0]], m.positions[f[1]], m.positions[f[2]]}, material});
}

}  // namespace rtvk::test
