// Vertex tangents for normal maps: generated per glTF's convention (host/formats/mesh_tangents),
// read from a glTF file's TANGENT, and the tangent at a hit on the CPU, through an instance too.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "bvh_world.h"
#include "hittable_list.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
#include "mesh_tangents.h"
#include "tangent_helpers.h"
#include "world.h"

namespace rtvk {
namespace {

using test::affine_uv;

void expect_tangent_near(const vec3& got, const vec3& want, double eps) {
  EXPECT_NEAR(got.x, want.x, eps);
  EXPECT_NEAR(got.y, want.y, eps);
  EXPECT_NEAR(got.z, want.z, eps);
}

scene tangent_grid(bool mirror) {
  scene s;
  s.materials.push_back({"mapped", test::normal_mapped_pbr()});
  test::add_uv_grid(s, affine_uv{}, 4, mirror);
  generate_tangents(s, 0);
  return s;
}

// An affine uv map has dp/du = U everywhere: every vertex's tangent is U made unit, w = +1 (the
// bitangent cross(n, U) leans along V).
TEST(Tangents, GeneratedTangentsAreDpDuOnAnAffineUvMap) {
  const scene s = tangent_grid(false);
  const affine_uv f;
  for (const triangle_shading& sh : s.shading) {
    ASSERT_TRUE(sh.has_tangent);
    for (const glm::vec4& t : sh.tangent) {
      expect_tangent_near(vec3(t), glm::normalize(f.U), 1e-6);
      EXPECT_EQ(t.w, 1.0f);
    }
  }
}

// The right half's uv are the left's mirrored (u -> 2 - u): there dp/du = -U and the faces turn
// the other way, w = -1. The seam's vertices (same position, normal and uv on both sides) are
// split by handedness, so each side keeps its own tangent there.
TEST(Tangents, MirroredUvGetHandednessMinusOneAndTheSeamSplits) {
  const scene s = tangent_grid(true);
  const affine_uv f;
  int mirrored = 0, plain = 0;
  for (const triangle& tri : s.triangles) {
    const triangle_shading& sh = s.shading[std::size_t(tri.shading)];
    // The face's side: its centroid's distance along U from the seam (u = 1).
    const point3 c = (tri.p[0] + tri.p[1] + tri.p[2]) / 3.0;
    const bool right = glm::dot(c - (f.origin + f.U), glm::cross(f.V, f.normal())) > 0;
    for (const glm::vec4& t : sh.tangent) {
      expect_tangent_near(vec3(t), (right ? -1.0 : 1.0) * glm::normalize(f.U), 1e-6);
      EXPECT_EQ(t.w, right ? -1.0f : 1.0f);
    }
    (right ? mirrored : plain)++;
  }
  EXPECT_EQ(mirrored, 16);
  EXPECT_EQ(plain, 16);
}

// Only normal-mapped materials' triangles get tangents: the others pay nothing.
TEST(Tangents, TrianglesWithoutANormalMapGetNone) {
  scene s;
  s.materials.push_back({"plain", material{}});
  test::add_uv_grid(s, affine_uv{}, 2, false);
  generate_tangents(s, 0);
  for (const triangle_shading& sh : s.shading) EXPECT_FALSE(sh.has_tangent);
}

// A one-triangle glTF with NORMAL, TEXCOORD_0 and TANGENT (w = -1, xyz not unit), its node
// mirroring x: the tangents come back placed (x negated), unit, and with w flipped to +1, the
// vertices' order swapped as the builder swaps a mirrored face's.
TEST(Tangents, AGltfFilesTangentsAreReadAndPlaced) {
  const float data[] = {
      0,    0,    0, 1,  0, 0, 0, 1,  0,              // POSITION
      0,    0,    1, 0,  0, 1, 0, 0,  1,              // NORMAL
      0,    0,    1, 0,  0, 1,                        // TEXCOORD_0
      0.6f, 0.8f, 0, -1, 2, 0, 0, -1, 0, 0.5f, 0, -1  // TANGENT
  };
  std::string bin(sizeof data, '\0');
  std::memcpy(bin.data(), data, sizeof data);
  const auto view = [](int offset, int bytes) {
    return "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
           ",\"byteLength\":" + std::to_string(bytes) + "}";
  };
  const auto accessor = [](int v, const char* type) {
    return "{\"bufferView\":" + std::to_string(v) + ",\"componentType\":5126,\"count\":3," +
           "\"type\":\"" + type + "\"" + (v == 0 ? ",\"min\":[0,0,0],\"max\":[1,1,0]" : "") + "}";
  };
  const std::string doc =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":[{\"mesh\":0,\"scale\":[-1,1,1]}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,"
      "\"TEXCOORD_0\":2,\"TANGENT\":3}}]}],"
      "\"buffers\":[{\"uri\":\"data:application/octet-stream;base64," +
      test::base64(bin) + "\",\"byteLength\":" + std::to_string(bin.size()) +
      "}],\"bufferViews\":[" + view(0, 36) + "," + view(36, 36) + "," + view(72, 24) + "," +
      view(96, 48) + "],\"accessors\":[" + accessor(0, "VEC3") + "," + accessor(1, "VEC3") + "," +
      accessor(2, "VEC2") + "," + accessor(3, "VEC4") + "]}";
  scene s;
  load_mesh_bytes(s, doc, "gltf", "t.gltf", "", {});
  ASSERT_EQ(s.triangles.size(), 1u);
  const triangle_shading& sh = s.shading[std::size_t(s.triangles[0].shading)];
  ASSERT_TRUE(sh.has_tangent);
  expect_tangent_near(vec3(sh.tangent[0]), vec3(-0.6, 0.8, 0), 1e-6);
  expect_tangent_near(vec3(sh.tangent[1]), vec3(0, 1, 0), 1e-6);   // the file's third vertex
  expect_tangent_near(vec3(sh.tangent[2]), vec3(-1, 0, 0), 1e-6);  // its second
  for (const glm::vec4& t : sh.tangent) EXPECT_EQ(t.w, 1.0f);
}

// An OBJ with uv and normals gets tangents where its faces take a normal-mapped material (here
// the scene's, by the placement), generated in scene space: a mirroring placement turns the uv
// frame over (w = -1); with the file's own material (no normal map) it gets none.
TEST(Tangents, AnObjsNormalMappedFacesGetGeneratedTangentsAfterPlacement) {
  const std::string obj =
      "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n";
  for (const double mirror : {1.0, -1.0}) {
    scene s;
    s.materials.push_back({"mapped", test::normal_mapped_pbr()});
    mesh_placement how;
    how.material = 0;
    how.placement = make_transform(vec3(mirror, 1, 1), vec3(0, 0, 1), 0, vec3(0));
    load_mesh_bytes(s, obj, "obj", "q.obj", "", how);
    ASSERT_EQ(s.triangles.size(), 2u);
    for (const triangle_shading& sh : s.shading) {
      ASSERT_TRUE(sh.has_tangent);
      for (const glm::vec4& t : sh.tangent) {
        expect_tangent_near(vec3(t), vec3(mirror, 0, 0), 1e-6);
        EXPECT_EQ(t.w, float(mirror));
      }
    }
  }
  scene plain;
  load_mesh_bytes(plain, obj, "obj", "q.obj", "", {});
  for (const triangle_shading& sh : plain.shading) EXPECT_FALSE(sh.has_tangent);
}

// A ray's hit on the grid carries the vertex tangents blended (U made unit, w = +1 from the
// front, -1 from behind where the record's normal is turned over); through an instance that
// rotates and stretches, M U made unit; through a mirroring one, w flips again.
TEST(Tangents, TheTangentAtAHitIsTheAnalyticOneThroughInstancesToo) {
  const scene flat = tangent_grid(false);
  const affine_uv f;
  const point3 target = f.origin + 0.7 * f.U + 1.1 * f.V;
  for (const double side : {1.0, -1.0}) {
    const point3 from = target + side * 2.0 * f.normal();
    for (const bool tree : {true, false}) {
      const bvh_world bvh(flat);
      const hittable_list list = make_world(flat);
      const hittable& world = tree ? static_cast<const hittable&>(bvh) : list;
      hit_record rec;
      ASSERT_TRUE(world.hit(ray(from, target - from), 1e-6, INFINITY, rec));
      expect_tangent_near(vec3(rec.tangent), glm::normalize(f.U), 1e-9);
      EXPECT_EQ(rec.tangent.w, side);
    }
  }
  for (const double mirror : {1.0, -1.0}) {
    scene s;
    s.materials = flat.materials;
    object_group g;
    g.triangles = flat.triangles;
    g.shading = flat.shading;
    s.groups.push_back(g);
    const transform m = make_transform(vec3(mirror * 2, 1, 0.5), vec3(1, 2, 3), 40, vec3(1, 0, 0));
    s.instances.push_back({0, m});
    const point3 at = m.apply_point(target);
    const vec3 n = m.apply_normal(f.normal());
    const point3 from = at + 2.0 * n;
    for (const bool tree : {true, false}) {
      const bvh_world bvh(s);
      const hittable_list list = make_world(s);
      const hittable& world = tree ? static_cast<const hittable&>(bvh) : list;
      hit_record rec;
      ASSERT_TRUE(world.hit(ray(from, at - from), 1e-6, INFINITY, rec));
      expect_tangent_near(vec3(rec.tangent), glm::normalize(m.apply_vector(f.U)), 1e-9);
      EXPECT_EQ(rec.tangent.w, mirror);
      EXPECT_NEAR(glm::dot(vec3(rec.tangent), rec.normal), 0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace rtvk
