// OBJ files as users have them (tests/data/obj): McGuire's Cornell box, concave faces cut in
// their plane, Windows paths, several MTL files, missing files drawn gray with a warning, two
// materials on one map, vertex colors, non-finite numbers refused by line.
#include <gtest/gtest.h>

#include <fstream>

#include "errors.h"
#include "image_io.h"
#include "mesh_file.h"
#include "obj_polygon.h"
#include "process.h"
#include "render_cpu.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const std::filesystem::path data = std::filesystem::path(RTVK_TEST_DATA) / "obj";

void write(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

const named_material& material_of(const scene& s, const triangle& t) {
  return s.materials[std::size_t(t.material)];
}

double area(const triangle& t) {
  return 0.5 * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
}

// Whether p (in the face's plane) lies strictly inside t.
bool covers(const triangle& t, const point3& p) {
  const vec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
  for (int k = 0; k < 3; ++k)
    if (!(glm::dot(glm::cross(t.p[(k + 1) % 3] - t.p[k], p - t.p[k]), n) > 0)) return false;
  return true;
}

TEST(ObjFiles, McGuiresCornellBoxHasItsLampRedAndGreenWalls) {
  const scene s = mesh_scene(data / "cornell-box" / "CornellBox-Original.obj");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  ASSERT_EQ(s.triangles.size(), 36u);  // 18 quads: 5 walls, two boxes of 6, the lamp
  int lamp = 0, red = 0, green = 0;
  for (const triangle& t : s.triangles) {
    const named_material& m = material_of(s, t);
    if (m.m.emission != color(0)) {
      ++lamp;
      EXPECT_NE(m.name.find("CornellBox-Original.obj:light"), std::string::npos) << m.name;
      EXPECT_EQ(m.m.emission, color(17, 12, 4));
      EXPECT_NEAR(t.p[0].y, 1.98, 1e-6);  // tinyobjloader's floats
    }
    red += glm::distance(m.m.albedo, color(0.63, 0.065, 0.05)) < 1e-6;
    green += glm::distance(m.m.albedo, color(0.14, 0.45, 0.091)) < 1e-6;
  }
  EXPECT_EQ(lamp, 2);
  EXPECT_EQ(red, 2);
  EXPECT_EQ(green, 2);
}

// An L-shaped hexagon, started at the corner where a fan would cross the notch, in a tilted
// plane: its triangles cover its area, 3, and leave the notch's center (1.5, 1.5) uncovered.
TEST(ObjFiles, AConcaveFaceKeepsItsShape) {
  const std::vector<glm::dvec2> l = {{2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}};
  const auto place = [](const glm::dvec2& q) { return point3(q.x, 0.6 * q.y, 0.8 * q.y); };
  std::string obj;
  for (const glm::dvec2& q : l) {
    const point3 p = place(q);
    obj +=
        "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  }
  obj += "f 1 2 3 4 5 6\n";
  scene s;
  load_mesh_bytes(s, obj, "obj", "l.obj", "", {});
  ASSERT_EQ(s.triangles.size(), 4u);
  double total = 0;
  for (const triangle& t : s.triangles) {
    total += area(t);
    EXPECT_FALSE(covers(t, place({1.5, 1.5}))) << "the notch is covered";
    EXPECT_GT(glm::dot(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]), vec3(0, -0.8, 0.6)), 0)
        << "wound as the face is";
  }
  EXPECT_NEAR(total, 3, 1e-6);
  bool inside = false;
  for (const triangle& t : s.triangles) inside = inside || covers(t, place({0.5, 1.5}));
  EXPECT_TRUE(inside) << "the L's upper arm is not covered";
}

// Every start of a U and of a ring cut open (two corners at each end of the cut): the triangles
// add up to the face's area, none wound backwards (which is how overlaps would show).
TEST(ObjFiles, UAndCutRingFacesFromEveryStart) {
  const std::vector<std::vector<vec3>> faces = {
      {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}},
      {{0, 0, 0},
       {4, 0, 0},
       {4, 4, 0},
       {0, 4, 0},
       {0, 2, 0},
       {1, 2, 0},
       {1, 3, 0},
       {3, 3, 0},
       {3, 1, 0},
       {1, 1, 0},
       {1, 2, 0},
       {0, 2, 0}}};
  const double areas[] = {7, 12};
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t start = 0; start < faces[f].size(); ++start) {
      std::vector<vec3> p(faces[f].begin() + std::ptrdiff_t(start), faces[f].end());
      p.insert(p.end(), faces[f].begin(), faces[f].begin() + std::ptrdiff_t(start));
      const auto triangles = triangulate_polygon(p);
      ASSERT_EQ(triangles.size(), p.size() - 2);
      double total = 0;
      for (const auto& t : triangles) {
        const double z = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]).z;
        EXPECT_GE(z, 0) << f << " from " << start;
        total += 0.5 * z;
      }
      EXPECT_NEAR(total, areas[f], 1e-9) << f << " from " << start;
    }
}

// Windows' separators, two MTL files on one mtllib line, one more on another, vertex colors.
TEST(ObjFiles, WindowsPathsSeveralMtlFilesAndVertexColors) {
  const test::temp_dir dir;
  std::filesystem::create_directories(dir.path() / "maps");
  write_image(image_rgb8{1, 1, {255, 255, 255}}, dir.path() / "maps" / "white.png");
  write(dir.path() / "a.mtl", "newmtl red\nKd 1 0 0\nmap_Kd .\\maps\\white.png\n");
  write(dir.path() / "b.mtl", "newmtl green\nKd 0 1 0\nmap_Kd maps\\white.png\n");
  write(dir.path() / "c.mtl", "newmtl glow\nKe 2 2 2\n");
  // Red at x in [0, 1], green at x in [2, 3], the glowing face out of view behind.
  write(dir.path() / "m.obj",
        "mtllib a.mtl b.mtl\nmtllib c.mtl\nv 0 0 0 1 0.5 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\n"
        "v 2 0 0\nv 3 0 0\nv 2 1 0\nv 0 0 -9\nv 1 0 -9\nv 0 1 -9\nvt 0 0\n"
        "usemtl red\nf 1/1 2/1 3/1\nusemtl green\nf 4/1 5/1 6/1\nusemtl glow\nf 7 8 9\n");
  const scene s = mesh_scene(dir.path() / "m.obj");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  ASSERT_EQ(s.triangles.size(), 3u);
  // Red and green on one map: two textures, their own tints, one decoded image.
  const material& red = material_of(s, s.triangles[0]).m;
  const material& green = material_of(s, s.triangles[1]).m;
  ASSERT_GE(red.texture, 0);
  ASSERT_GE(green.texture, 0);
  EXPECT_EQ(s.textures[std::size_t(red.texture)].even, color(1, 0, 0));
  EXPECT_EQ(s.textures[std::size_t(green.texture)].even, color(0, 1, 0));
  EXPECT_EQ(s.textures[std::size_t(red.texture)].image,
            s.textures[std::size_t(green.texture)].image);
  EXPECT_EQ(material_of(s, s.triangles[2]).m.emission, color(2));
  ASSERT_GE(s.triangles[0].shading, 0);
  const triangle_shading& sh = s.shading[std::size_t(s.triangles[0].shading)];
  EXPECT_TRUE(sh.has_color);
  EXPECT_EQ(sh.color[0], glm::vec4(1, 0.5f, 0, 1));
  EXPECT_EQ(sh.color[2], glm::vec4(0, 0, 1, 1));
  // Both colors show: each face drawn flat (unlit) through one pixel in front of it.
  scene flat = s;
  for (named_material& m : flat.materials) m.m.type = material_type::flat;
  for (triangle_shading& t : flat.shading) t.has_color = false;  // the tints alone
  flat.render.width = flat.render.spp = 1;
  flat.render.aspect = 1;
  const auto seen = [&](double x) {
    camera_pose& c = main_camera(flat).pose;
    c.lookfrom = point3(x, 0.25, 5);
    c.lookat = point3(x, 0.25, 0);
    c.vfov = 1;
    return render_cpu(test::scene_camera(flat), flat, flat.render).at(0, 0);
  };
  EXPECT_EQ(seen(0.25), color(1, 0, 0));
  EXPECT_EQ(seen(2.25), color(0, 1, 0));
}

// A missing MTL: one warning naming it, the faces gray, the file still drawn.
TEST(ObjFiles, AMissingMtlIsAWarningAndGray) {
  const test::temp_dir dir;
  write(dir.path() / "m.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  const scene s = mesh_scene(dir.path() / "m.obj");
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("mtllib gone.mtl: no such file"), std::string::npos)
      << s.warnings[0];
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(material_of(s, s.triangles[0]).m.albedo, color(0.7));
  const auto r =
      test::run_rtvk({"render", "--scene", (dir.path() / "m.obj").string(), "--width", "8", "--spp",
                      "1", "--backend", "cpu", "-o", (dir.path() / "m.png").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("gone.mtl"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "m.png"));
}

// nan, inf and numbers past a double's range are refused naming the line, exit 2.
TEST(ObjFiles, NonFiniteVerticesAreRefusedByLine) {
  const std::string head = "v 0 0 0\nv 1 0 0\n";
  for (const std::string bad : {"v nan 0 0", "v 0 inf 0", "v 0 0 -1e999", "v 0 0 0 1 NaN 1"}) {
    std::string got;
    try {
      scene s;
      load_mesh_bytes(s, head + bad + "\nf 1 2 3\n", "obj", "m.obj", "", {});
    } catch (const usage_error& e) {
      got = e.what();
    }
    EXPECT_EQ(got.rfind("m.obj:3: v: number ", 0), 0u) << bad << ": " << got;
    EXPECT_NE(got.find("is not finite"), std::string::npos) << bad << ": " << got;
  }
  const test::temp_dir dir;
  write(dir.path() / "nan.obj", head + "v nan 0 0\nf 1 2 3\n");
  const auto r = test::run_rtvk({"render", "--scene", (dir.path() / "nan.obj").string(), "-o",
                                 (dir.path() / "x.png").string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("nan.obj:3: v: number 1 is not finite, got 'nan'"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

// A Latin-1 material name (0xE9, "é" on Windows) made `rtvk scene dump` exit 1 (nlohmann::json
// throws on bytes that are not UTF-8): names are now read as UTF-8 where they are, Latin-1 byte
// by byte where not, and dump and read back unchanged.
TEST(ObjFiles, AnyBytesInANameSurviveSceneDump) {
  const test::temp_dir dir;
  write(dir.path() / "m.mtl",
        "newmtl caf\xe9\nKd 1 0 0\nnewmtl na\xc3\xafve\nKd 0 1 0\n"
        "newmtl x\x80\xff\xc3\nKd 0 0 1\n");
  write(dir.path() / "m.obj",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl caf\xe9\nf 1 2 3\n"
        "usemtl na\xc3\xafve\nf 1 3 2\nusemtl x\x80\xff\xc3\nf 2 1 3\n");
  const scene s = mesh_scene(dir.path() / "m.obj");
  ASSERT_EQ(s.materials.size(), 3u);
  const std::string prefix = (dir.path() / "m.obj").string() + ":";
  EXPECT_EQ(s.materials[0].name, prefix + "caf\xc3\xa9");                // Latin-1 read
  EXPECT_EQ(s.materials[1].name, prefix + "na\xc3\xafve");               // UTF-8 kept
  EXPECT_EQ(s.materials[2].name, prefix + "x\xc2\x80\xc3\xbf\xc3\x83");  // each bad byte
  const std::string dumped = dump_scene_json(s);
  write(dir.path() / "d.json", dumped);
  const scene back = load_scene_file(dir.path() / "d.json");
  ASSERT_EQ(back.materials.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(back.materials[k].name, s.materials[k].name);
  EXPECT_EQ(dump_scene_json(back), dumped);
  const auto r = test::run_rtvk({"scene", "dump", (dir.path() / "m.obj").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("caf\xc3\xa9"), std::string::npos);
}

// An MTL map is decoded as sRGB (viewers' reading); a dumped scene must say so, or reading it back
// decodes the same file by the book's gamma 2.2 (the dump wrote no "color_space": texel 56, not
// 55, for a gray 128).
TEST(ObjFiles, ADumpedSceneReadsItsMapsBackAsSrgb) {
  const test::temp_dir dir;
  image_rgb8 gray;
  gray.width = gray.height = 2;
  gray.rgb.assign(12, 128);
  write(dir.path() / "t.png", encode_png(gray));
  write(dir.path() / "t.mtl", "newmtl a\nKd 1 1 1\nmap_Kd t.png\n");
  write(dir.path() / "t.obj",
        "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl a\n"
        "f 1/1 2/2 3/3\n");
  const scene s = mesh_scene(dir.path() / "t.obj");
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].image->texels[0] & 255u, 55u);  // sRGB: 0.2158 -> floor(256 v)
  write(dir.path() / "d.json", dump_scene_json(s));
  const scene back = load_scene_file(dir.path() / "d.json");
  ASSERT_EQ(back.textures.size(), 1u);
  EXPECT_EQ(back.textures[0].color_space, texel_encoding::srgb);
  EXPECT_EQ(back.textures[0].image->texels, s.textures[0].image->texels);
}

// Each row of docs/mesh-formats.md's MTL table, as Blender's importer maps MTL to its Principled
// BSDF: one material per row (or a few rows), each parameter asserted exactly.
TEST(ObjFiles, MtlStatementsMapToThePbrMaterialAsTheTableSays) {
  const test::temp_dir dir;
  write_image(image_rgb8{1, 1, {188, 188, 188}}, dir.path() / "g.png");
  write(dir.path() / "m.mtl",
        "newmtl bare\n"  // nothing said: defaults
        "newmtl plastic\nKd 0.5 0.25 1\nKs 0.2 0.2 0.2\nNs 250\nillum 2\nNi 1.45\n"
        "newmtl shiny\nillum 2\n"                                   // illum 2 without Ks, Ns
        "newmtl mirror\nKd 0.9 0.9 0.9\nKa 0.5 0.5 0.5\nillum 3\n"  // metallic mean(Ka)
        "newmtl chrome\nillum 5\nNs 1000\n"                         // no Ka: metallic 1
        "newmtl pbr\nKd 1 1 1\nPr 0.3\nPm 0.7\nNs 1000\nillum 3\nKa 0 0 0\n"
        "newmtl glass\nKd 0.9 1 0.9\nNi 1.33\nd 0.5\nillum 7\n"
        "newmtl water\nillum 4\nNi 0\n"  // Ni <= 0: 1.5
        "newmtl veil\nKd 1 0 0\nd 0.25\nKe 1 2 3\n"
        "newmtl velvet\nPs 0.6\nPc 0.8\nPcr 0.1\naniso 0.5\nTf 1 1 1\n"
        "newmtl coat\nPc 1\n"
        "newmtl maps\nPm 0\nmap_Pr g.png\nmap_Ps g.png\nnorm -bm 0.5 g.png\n"
        "newmtl bumpy\nmap_Bump g.png\nmap_Pm g.png\n");
  std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (const char* m : {"bare", "plastic", "shiny", "mirror", "chrome", "pbr", "glass", "water",
                        "veil", "velvet", "coat", "maps", "bumpy"})
    obj += std::string("usemtl ") + m + "\nf 1 2 3\n";
  write(dir.path() / "m.obj", obj);
  const scene s = mesh_scene(dir.path() / "m.obj");
  ASSERT_EQ(s.materials.size(), 13u);
  const auto at = [&](std::size_t k) -> const material& { return s.materials[k].m; };
  for (std::size_t k = 0; k < 13; ++k) EXPECT_EQ(at(k).type, material_type::pbr) << k;
  // bare: Blender's defaults (base 0.8), no highlight: specular 0, roughness 1, dielectric.
  EXPECT_EQ(at(0).albedo, color(0.8));
  EXPECT_EQ(at(0).pbr.specular, 0);
  EXPECT_EQ(at(0).pbr.roughness, 1);
  EXPECT_EQ(at(0).pbr.metallic, 0);
  EXPECT_EQ(at(0).pbr.ior, 1.5);
  // plastic: specular 2 mean(Ks), roughness 1 - sqrt(Ns / 1000), ior Ni.
  EXPECT_NEAR(at(1).albedo.g, 0.25, 1e-7);
  EXPECT_NEAR(at(1).pbr.specular, 0.4, 1e-7);
  EXPECT_NEAR(at(1).pbr.roughness, 0.5, 1e-7);
  EXPECT_NEAR(at(1).pbr.ior, 1.45, 1e-6);
  EXPECT_EQ(at(1).pbr.metallic, 0);
  // illum 2 without Ks: level 1, twice glTF's neutral (specular 1, the rest in its color, as
  // Blender's glTF exporter writes it); without Ns: smooth.
  EXPECT_EQ(at(2).pbr.specular, 1);
  EXPECT_EQ(at(2).pbr.specular_color, color(2));
  EXPECT_EQ(at(1).pbr.specular_color, color(1));
  EXPECT_EQ(at(2).pbr.roughness, 0);
  EXPECT_NEAR(at(3).pbr.metallic, 0.5, 1e-7);  // illum 3: mean(Ka)
  EXPECT_EQ(at(3).pbr.roughness, 1);
  EXPECT_EQ(at(4).pbr.metallic, 1);  // illum 5, no Ka
  EXPECT_EQ(at(4).pbr.roughness, 0);
  EXPECT_NEAR(at(5).pbr.roughness, 0.3, 1e-7);  // Pr and Pm over Ns and illum
  EXPECT_NEAR(at(5).pbr.metallic, 0.7, 1e-7);
  // glass: transmission 1 of index Ni, metallic 0, d not drawn again; no Ni: 1.5.
  EXPECT_EQ(at(6).pbr.transmission, 1);
  EXPECT_NEAR(at(6).pbr.ior, 1.33, 1e-6);
  EXPECT_EQ(at(6).pbr.metallic, 0);
  EXPECT_EQ(at(6).opacity, 1);
  EXPECT_EQ(at(6).alpha, alpha_mode::opaque);
  EXPECT_EQ(at(7).pbr.ior, 1.5);
  EXPECT_EQ(at(7).albedo, color(1));  // glass without Kd: untinted
  EXPECT_EQ(at(8).opacity, 0.25);     // d: alpha-blended
  EXPECT_EQ(at(8).alpha, alpha_mode::blend);
  EXPECT_EQ(at(8).emission, color(1, 2, 3));
  // velvet: sheen (Ps, Ps, Ps) at roughness 0.5, clearcoat 0.25 Pc of roughness Pcr; aniso and
  // Tf not read (no transmission).
  EXPECT_NEAR(at(9).pbr.sheen_color.r, 0.6, 1e-7);
  EXPECT_EQ(at(9).pbr.sheen_roughness, 0.5);
  EXPECT_NEAR(at(9).pbr.clearcoat, 0.2, 1e-7);
  EXPECT_NEAR(at(9).pbr.clearcoat_roughness, 0.1, 1e-7);
  EXPECT_EQ(at(9).pbr.transmission, 0);
  EXPECT_EQ(at(10).pbr.clearcoat, 0.25);
  EXPECT_NEAR(at(10).pbr.clearcoat_roughness, 0.03, 1e-12);  // Blender's default coat roughness
  // maps: map_Pr alone with metallic 0 is the metallic-roughness texture, map_Ps the sheen's,
  // norm the normal map with -bm its scale; all decoded as data (188 stays 188).
  const pbr_material& p = at(11).pbr;
  for (int t : {p.metallic_roughness_texture, p.sheen_color_texture, p.normal_texture}) {
    ASSERT_GE(t, 0);
    EXPECT_EQ(s.textures[std::size_t(t)].color_space, texel_encoding::linear);
    EXPECT_EQ(s.textures[std::size_t(t)].image->texels[0] & 255u, 188u);
  }
  EXPECT_EQ(p.normal_scale, 0.5);
  // bumpy: map_Bump is the normal map (Blender's reading); a lone map_Pm cannot be one texture
  // with a roughness: a warning names it.
  EXPECT_GE(at(12).pbr.normal_texture, 0);
  EXPECT_EQ(at(12).pbr.metallic_roughness_texture, -1);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("material bumpy: map_Pm g.png: not drawn"), std::string::npos)
      << s.warnings[0];
}

}  // namespace
}  // namespace rtvk
