// Meshes from files: OBJ, glTF and .glb of one mesh are the same triangles and the same image;
// scene files place them; bad files are refused with the file and where in it.
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "mesh_file.h"
#include "mesh_helpers.h"
#include "process.h"
#include "quantize.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

void write(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// The message of the usage_error loading `bytes` as `kind` throws ("" when none).
std::string refusal(const std::string& bytes, const std::string& kind) {
  scene s;
  try {
    load_mesh_bytes(s, bytes, kind, "m." + kind, "/nonexistent-rtvk-dir", {});
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}

TEST(MeshFile, ObjGltfAndGlbOfOneMeshAreTheSameTrianglesAndImage) {
  const test::temp_dir dir;
  const test::indexed_mesh m = test::cube_sphere(4, 0.5);
  write(dir.path() / "m.obj", test::obj_text(m));
  write(dir.path() / "m.gltf", test::gltf_json(m));
  write(dir.path() / "m.glb", test::glb_bytes(m));
  std::vector<scene> scenes;
  for (const char* name : {"m.obj", "m.gltf", "m.glb"}) {
    scene s = mesh_scene(dir.path() / name);
    ASSERT_EQ(s.triangles.size(), m.faces.size()) << name;
    for (std::size_t f = 0; f < m.faces.size(); ++f)
      for (std::size_t k = 0; k < 3; ++k)
        ASSERT_EQ(s.triangles[f].p[k], m.positions[m.faces[f][k]]) << name << " face " << f;
    s.render.width = 48;
    s.render.spp = 2;
    scenes.push_back(std::move(s));
  }
  const image_rgb8 obj = test::cpu_image(scenes[0]);
  EXPECT_EQ(test::cpu_image(scenes[1]).rgb, obj.rgb);
  EXPECT_EQ(test::cpu_image(scenes[2]).rgb, obj.rgb);
  // The framing camera sees the mesh: some pixels are not the sky.
  const image_rgb8 sky = test::cpu_image([&] {
    scene e = scenes[0];
    e.triangles.clear();
    return e;
  }());
  EXPECT_NE(obj.rgb, sky.rgb);
}

TEST(MeshFile, GltfNodeMatricesAndMaterialsAreApplied) {
  const test::indexed_mesh m = test::cube_sphere(2, 1.0);
  // Column-major: scale 2, then move by (10, 0, 0).
  std::string doc = test::gltf_json(m, "", "2,0,0,0, 0,2,0,0, 0,0,2,0, 10,0,0,1");
  doc.insert(doc.rfind('}'),
             ",\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,1,1],"
             "\"metallicFactor\":0.9,\"roughnessFactor\":0.3}}]");
  doc.replace(doc.find("\"indices\":1"), 11, "\"indices\":1,\"material\":0");
  scene s;
  load_mesh_bytes(s, doc, "gltf", "m.gltf", "", {});
  ASSERT_EQ(s.triangles.size(), m.faces.size());
  EXPECT_EQ(s.triangles[0].p[0], 2.0 * m.positions[m.faces[0][0]] + vec3(10, 0, 0));
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].m.type, material_type::metal);
  EXPECT_EQ(s.materials[0].m.albedo, color(0.5, 0.25, 1));
  EXPECT_EQ(s.materials[0].m.fuzz, 0.3);
}

TEST(MeshFile, ObjNormalsShadeSmoothAndMtlMaterialsMap) {
  const test::temp_dir dir;
  write(dir.path() / "m.mtl",
        "newmtl red\nKd 0.9 0.1 0.1\nillum 2\nnewmtl glass\nNi 1.33\nd 0.5\n");
  write(dir.path() / "m.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
        "usemtl red\nf 1/1/1 2/2/1 3/3/1\nusemtl glass\nf 2 4 3\n");
  scene s;
  load_mesh(s, dir.path() / "m.obj", {});
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[std::size_t(s.triangles[0].material)].m.type, material_type::lambertian);
  EXPECT_EQ(s.materials[std::size_t(s.triangles[0].material)].m.albedo, color(0.9f, 0.1f, 0.1f));
  EXPECT_EQ(s.materials[std::size_t(s.triangles[1].material)].m.type, material_type::dielectric);
  EXPECT_NEAR(s.materials[std::size_t(s.triangles[1].material)].m.ir, 1.33, 1e-6);
  ASSERT_GE(s.triangles[0].shading, 0);
  EXPECT_TRUE(s.shading[std::size_t(s.triangles[0].shading)].has_normals());
  EXPECT_EQ(s.shading[std::size_t(s.triangles[0].shading)].uv[1], glm::dvec2(1, 0));
  EXPECT_EQ(s.triangles[1].shading, -1);  // no normals, no uv: flat
}

TEST(MeshFile, AScenePlacesMeshesRelativeToItsFileWithAMaterial) {
  const test::temp_dir dir;
  std::filesystem::create_directories(dir.path() / "models");
  write(dir.path() / "models" / "m.obj", test::obj_text(test::cube_sphere(2, 1.0)));
  write(dir.path() / "s.json",
        R"({"materials": {"gold": {"type": "metal", "albedo": [0.8, 0.6, 0.2]}},
            "meshes": [{"file": "models/m.obj", "material": "gold",
                        "transform": {"scale": 2, "translate": [0, 1, 0]}}]})");
  const scene s = load_scene_file(dir.path() / "s.json");
  ASSERT_EQ(s.triangles.size(), 48u);
  EXPECT_EQ(s.materials.size(), 1u);
  for (const triangle& t : s.triangles) {
    EXPECT_EQ(t.material, 0);
    for (const point3& p : t.p) EXPECT_NEAR(glm::length(p - point3(0, 1, 0)), 2, 0.05);
  }
}

TEST(MeshFile, BadFilesAreRefusedWithTheFileAndWhereInIt) {
  const test::indexed_mesh m = test::cube_sphere(1, 1.0);
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "obj"),
            "m.obj: shape \"\" face 0: vertex index 9 is not one of the 3 positions");
  EXPECT_EQ(refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4\n", "obj"),
            "m.obj: shape \"\" face 0: normal index 4 is not one of the 1 normals");
  // NaN positions, in a glTF buffer (a text OBJ may spell them many ways; its parser's reading
  // of them is its own).
  test::indexed_mesh bad = m;
  bad.positions[2].y = std::nan("");
  EXPECT_EQ(refusal(test::gltf_json(bad), "gltf").rfind("m.gltf: mesh 0 primitive 0 triangle ", 0),
            0u);
  EXPECT_NE(refusal(test::gltf_json(bad), "gltf").find("position is not finite"),
            std::string::npos);
  // A truncated .glb, and an accessor past its buffer.
  const std::string glb = test::glb_bytes(m);
  EXPECT_NE(refusal(glb.substr(0, glb.size() / 2), "glb"), "");
  std::string past = test::gltf_json(m);
  past.replace(past.find("\"count\":8"), 9, "\"count\":99");
  EXPECT_EQ(refusal(past, "gltf").rfind("m.gltf: mesh 0 primitive 0 POSITION (accessor 0)", 0), 0u)
      << refusal(past, "gltf");
  // Indices past the vertices.
  std::string far = test::gltf_json(test::cube_sphere(1, 1.0));
  EXPECT_EQ(refusal("not json at all", "gltf").rfind("m.gltf: ", 0), 0u);
  EXPECT_EQ(refusal("", "obj"), "") << "an empty OBJ is read as no faces (load_mesh refuses it)";
}

// Found in review: a byteOffset near 2^64 wrapped the bounds check's sum (a read before the
// buffer); a node reached twice (a DAG of 60 levels) was walked 2^60 times; two unnamed
// materials shared one name in dumps; a long mtllib name threw a filesystem error (exit 1).
TEST(MeshFile, HostileGltfAndObjAreRefusedNotFollowed) {
  const test::indexed_mesh m = test::cube_sphere(1, 1.0);
  std::string wrap = test::gltf_json(m);
  wrap.replace(wrap.find("\"componentType\":5126"), 20,
               "\"byteOffset\":18446744073709551580,\"componentType\":5126");
  EXPECT_NE(refusal(wrap, "gltf").find("points outside its buffer"), std::string::npos)
      << refusal(wrap, "gltf");
  std::string dag = test::gltf_json(m);
  dag.replace(dag.find("\"nodes\":[{\"mesh\":0}]"), 20,
              "\"nodes\":[{\"children\":[1,1]},{\"mesh\":0}]");
  EXPECT_EQ(refusal(dag, "gltf"), "m.gltf: node 1: is reached twice (glTF nodes form trees)");
  EXPECT_EQ(refusal("mtllib " + std::string(300, 'x') + ".mtl\nv 0 0 0\n", "obj"),
            "m.obj: mtllib " + std::string(300, 'x') + ".mtl: no such file beside the OBJ");
  std::string two = test::gltf_json(m);
  two.insert(two.rfind('}'),
             ",\"materials\":[{\"pbrMetallicRoughness\":{\"metallicFactor\":0}},"
             "{\"pbrMetallicRoughness\":{\"metallicFactor\":1}}]");
  scene s;
  load_mesh_bytes(s, two, "gltf", "m.gltf", "", {});
  load_mesh_bytes(s, two, "gltf", "m.gltf", "", {});  // placed twice
  // Each load: the file's two materials, and the gray one its material-less primitive gets.
  ASSERT_EQ(s.materials.size(), 6u);
  EXPECT_EQ(s.materials[0].name, "m.gltf:0");
  EXPECT_EQ(s.materials[1].name, "m.gltf:1");
  EXPECT_EQ(s.materials[2].name, "m.gltf:default");
  EXPECT_EQ(s.materials[3].name, "m.gltf:0#2");
  EXPECT_EQ(s.materials[4].name, "m.gltf:1#2");
  EXPECT_EQ(s.materials[5].name, "m.gltf:default#2");
}

// A mirroring placement (a negative scale, in the scene file or a glTF node) keeps each face's
// front where its vertex normals point: the winding is put back. Faces without area are dropped.
TEST(MeshFile, MirroredMeshesKeepTheirFrontsAndFacesWithoutAreaAreDropped) {
  // Faces 1 and 3 face +z (counter-clockwise from there, like the normal); face 2 is collinear.
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nvn 0 0 1\n"
      "f 1//1 2//1 3//1\nf 1//1 2//1 4//1\nf 2//1 4//1 3//1\n";
  for (const double sx : {1.0, -1.0}) {
    scene s;
    load_mesh_bytes(
        s, obj, "obj", "m.obj", "",
        {.material = -1, .placement = make_transform(vec3(sx, 1, 1), vec3(0, 1, 0), 0, vec3(0))});
    ASSERT_EQ(s.triangles.size(), 2u) << "the collinear face is dropped";
    for (const triangle& t : s.triangles) {
      const vec3 geometric = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
      const vec3 shading = s.shading[std::size_t(t.shading)].normal[0];
      EXPECT_GT(glm::dot(geometric, shading), 0) << "scale x " << sx;
    }
  }
}

TEST(MeshFile, TheCliRefusesBadMeshesWithExit2AndNoImage) {
  const test::temp_dir dir;
  write(dir.path() / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  write(dir.path() / "s.json", R"({"meshes": [{"file": "missing.obj"}]})");
  write(dir.path() / "flat.json",
        R"({"materials": {"m": {"type": "normal"}},
            "quads": [{"Q": [0,0,0], "u": [1,0,0], "v": [0,1,0], "material": "m",
                       "transform": {"scale": [1, 0, 1]}}]})");
  const std::string out = (dir.path() / "o.png").string();
  const auto r1 =
      test::run_rtvk({"render", "--scene", (dir.path() / "bad.obj").string(), "-o", out});
  EXPECT_EQ(r1.status, 2);
  EXPECT_NE(r1.err.find("bad.obj: shape \"\" face 0: vertex index 7 is not one of the 3"),
            std::string::npos)
      << r1.err;
  const auto r2 =
      test::run_rtvk({"render", "--scene", (dir.path() / "s.json").string(), "-o", out});
  EXPECT_EQ(r2.status, 2);
  EXPECT_NE(r2.err.find("missing.obj"), std::string::npos) << r2.err;
  const auto r3 =
      test::run_rtvk({"render", "--scene", (dir.path() / "flat.json").string(), "-o", out});
  EXPECT_EQ(r3.status, 2);
  EXPECT_NE(r3.err.find("/quads/0/transform: the transform cannot place anything"),
            std::string::npos)
      << r3.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace rtvk
