// Meshes from files: OBJ, glTF and .glb of one mesh are the same triangles and the same image;
// scene files place them; bad files are refused with the file and where in it.
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "image_io.h"
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
  // Issue 45: glTF's own parameters, exactly (no longer a fuzz-0.3 metal because 0.9 >= 0.5).
  EXPECT_EQ(s.materials[0].m.type, material_type::pbr);
  EXPECT_EQ(s.materials[0].m.albedo, color(0.5, 0.25, 1));
  EXPECT_EQ(s.materials[0].m.pbr.metallic, 0.9);
  EXPECT_EQ(s.materials[0].m.pbr.roughness, 0.3);
}

// A glTF square of two triangles with texture coordinates, its first material's base color an
// embedded 2x1 PNG (red, blue), its second emissive.
std::string textured_gltf() {
  std::string bin;
  const auto put = [&bin](float f) { bin.append(reinterpret_cast<const char*>(&f), 4); };
  for (float p : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.f, 0.f, 1.f, 0.f}) put(p);
  for (float t : {0.f, 1.f, 1.f, 1.f, 1.f, 0.f, 0.f, 0.f}) put(t);  // glTF: v = 0 at the top
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) bin.append(reinterpret_cast<const char*>(&i), 4);
  const std::string png = encode_png(image_rgb8{2, 1, {255, 0, 0, 0, 0, 255}});
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
         R"("nodes":[{"mesh":0},{"mesh":1,"translation":[0,0,-1]}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]},)"
         R"({"primitives":[{"attributes":{"POSITION":0},"indices":2,"material":1}]}],)"
         R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0}},)"
         R"({"emissiveFactor":[1,0.5,0.25],"extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4}}}],)"
         R"("textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" +
         test::base64(png) + R"("}],"buffers":[{"uri":"data:application/octet-stream;base64,)" +
         test::base64(bin) +
         R"(","byteLength":104}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},)"
         R"({"buffer":0,"byteOffset":48,"byteLength":32},{"buffer":0,"byteOffset":80,"byteLength":24}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
         R"({"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},)"
         R"({"bufferView":2,"componentType":5125,"count":6,"type":"SCALAR"}]})";
}

TEST(MeshFile, GltfBaseColorTexturesAndEmissiveMaterialsAreDrawn) {
  const test::temp_dir dir;
  write(dir.path() / "sq.gltf", textured_gltf());
  write(dir.path() / "s.json", R"({"meshes":[{"file":"sq.gltf"}]})");
  const scene s = load_scene_file(dir.path() / "s.json");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].m.type, material_type::pbr);  // a dielectric: metallicFactor 0
  EXPECT_EQ(s.materials[0].m.pbr.metallic, 0);
  ASSERT_EQ(s.materials[0].m.texture, 0);
  ASSERT_EQ(s.textures.size(), 1u);
  ASSERT_EQ(s.textures[0].image->width, 2);
  EXPECT_EQ(s.textures[0].image->texels[0], 0xff0000ffu);
  EXPECT_EQ(s.textures[0].wrap_u, image_wrap::repeat);  // glTF's default sampler
  EXPECT_EQ(s.textures[0].even, color(1));              // the base color factor's default
  // Emission beside what the surface reflects (issue 44: no longer a lamp that reflects nothing);
  // the rest of the material is glTF's default, a rough metal.
  EXPECT_EQ(s.materials[1].m.type, material_type::pbr);
  EXPECT_EQ(s.materials[1].m.pbr.metallic, 1);
  EXPECT_EQ(s.materials[1].m.emission, color(4, 2, 1));
  // v flipped to rtvk's (the book's) up-from-the-bottom: the first vertex's (0, 1) is (0, 0).
  ASSERT_GE(s.triangles[0].shading, 0);
  const triangle_shading& sh = s.shading[std::size_t(s.triangles[0].shading)];
  EXPECT_TRUE(sh.has_uv);
  EXPECT_EQ(sh.uv[0], glm::dvec2(0, 0));
  EXPECT_EQ(sh.uv[2], glm::dvec2(1, 1));
  // Drawn: the left half of the square red, the right half blue (flat, unlit, to see texels).
  scene flat = s;
  flat.materials[0].m.type = material_type::flat;
  main_camera(flat).pose.lookfrom = point3(0.5, 0.5, 2);
  main_camera(flat).pose.lookat = point3(0.5, 0.5, 0);
  main_camera(flat).pose.vfov = 20;
  flat.render.width = 20;
  flat.render.aspect = 1;
  flat.render.spp = 1;
  const framebuffer fb = render_cpu(test::scene_camera(flat), flat, flat.render);
  EXPECT_EQ(fb.at(5, 10), color(1, 0, 0));
  EXPECT_EQ(fb.at(14, 10), color(0, 0, 1));
  // A dump names the image by the glTF it came from, and reads back the same.
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("sq.gltf#images/0"), std::string::npos) << dumped;
  write(dir.path() / "d.json", dumped);
  EXPECT_EQ(dump_scene_json(load_scene_file(dir.path() / "d.json")), dumped);
}

// An MTL's map_Kd: an image texture beside the OBJ, tinted by Kd and tiled; one decoded image
// for every material naming it; a material with an emissive texture in glTF stays diffuse.
TEST(MeshFile, ObjDiffuseMapsAreImageTexturesTintedByKd) {
  const test::temp_dir dir;
  write_image(image_rgb8{1, 1, {255, 255, 255}}, dir.path() / "white.png");
  write(dir.path() / "m.mtl",
        "newmtl a\nKd 0.5 0.25 1\nmap_Kd white.png\nnewmtl b\nKd 1 1 1\nmap_Kd white.png\n");
  write(dir.path() / "m.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 3 0\nvt 0 3\n"
        "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 3/3 2/2\n");
  const scene s = mesh_scene(dir.path() / "m.obj");
  // A texture per material (each its own Kd tint), one decoded image shared (issue 44: the
  // second material used to draw with the first one's tint).
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.materials[0].m.texture, 0);
  EXPECT_EQ(s.materials[1].m.texture, 1);
  EXPECT_EQ(s.textures[0].even, color(0.5, 0.25, 1));
  EXPECT_EQ(s.textures[1].even, color(1, 1, 1));
  EXPECT_EQ(s.textures[0].image, s.textures[1].image);
  EXPECT_EQ(s.textures[0].wrap_u, image_wrap::repeat);
  EXPECT_TRUE(std::filesystem::path(s.textures[0].file).is_absolute()) << s.textures[0].file;
  // A missing map_Kd is a warning naming it; the material is drawn with its Kd alone.
  write(dir.path() / "bad.mtl", "newmtl a\nKd 1 1 1\nmap_Kd nowhere.png\n");
  write(dir.path() / "bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  const scene bad = mesh_scene(dir.path() / "bad.obj");
  ASSERT_EQ(bad.warnings.size(), 1u);
  EXPECT_NE(bad.warnings[0].find("material a: map_Kd nowhere.png: no such file"), std::string::npos)
      << bad.warnings[0];
  EXPECT_EQ(bad.materials[0].m.texture, -1);
  // glTF: an emissive factor with an emissive texture (a glowing dial) is not a lamp.
  std::string doc = textured_gltf();
  doc.replace(doc.find(R"("emissiveFactor")"), 0, R"("emissiveTexture":{"index":0},)");
  scene g;
  load_mesh_bytes(g, doc, "gltf", "sq.gltf", "", {});
  EXPECT_EQ(g.materials[1].m.type, material_type::pbr);  // glTF's default metal, emissive
}

TEST(MeshFile, ObjNormalsShadeSmoothAndMtlMaterialsMap) {
  const test::temp_dir dir;
  write(dir.path() / "m.mtl",
        "newmtl red\nKd 0.9 0.1 0.1\nillum 2\nnewmtl glass\nNi 1.33\nd 0.5\nillum 7\n");
  write(dir.path() / "m.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\n"
        "usemtl red\nf 1/1/1 2/2/1 3/3/1\nusemtl glass\nf 2 4 3\n");
  scene s;
  load_mesh(s, dir.path() / "m.obj", {});
  ASSERT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.materials.size(), 2u);
  // Issue 45: MTL as Blender maps it to its Principled BSDF (docs/mesh-formats.md): illum 2 a
  // dielectric, illum 7 glass (transmission 1 of index Ni).
  const material& red = s.materials[std::size_t(s.triangles[0].material)].m;
  EXPECT_EQ(red.type, material_type::pbr);
  EXPECT_EQ(red.albedo, color(0.9f, 0.1f, 0.1f));
  EXPECT_EQ(red.pbr.metallic, 0);
  EXPECT_EQ(red.pbr.transmission, 0);
  const material& glass = s.materials[std::size_t(s.triangles[1].material)].m;
  EXPECT_EQ(glass.type, material_type::pbr);
  EXPECT_EQ(glass.pbr.transmission, 1);
  EXPECT_NEAR(glass.pbr.ior, 1.33, 1e-6);
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
  // A missing MTL is now drawn gray with a warning (issue 44), the long name said in it.
  scene long_name;
  load_mesh_bytes(long_name, "mtllib " + std::string(300, 'x') + ".mtl\nv 0 0 0\n", "obj", "m.obj",
                  "/nonexistent-rtvk-dir", {});
  ASSERT_EQ(long_name.warnings.size(), 1u);
  EXPECT_EQ(long_name.warnings[0], "m.obj: mtllib " + std::string(300, 'x') +
                                       ".mtl: no such file beside the OBJ; its materials are "
                                       "drawn gray");
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
