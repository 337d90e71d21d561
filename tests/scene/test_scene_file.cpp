#include <gtest/gtest.h>

#include <fstream>

#include <cstdio>

#include "errors.h"
#include "image_io.h"
#include "light_sources.h"
#include "render_helpers.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

TEST(SceneFile, BuiltinScenesRoundTripExactly) {
  for (const std::string& name : builtin_scene_names()) {
    const scene original = builtin_scene(name);
    const std::string dumped = dump_scene_json(original);
    const scene back = parse_scene_json(dumped, name + ".json");
    EXPECT_EQ(dump_scene_json(back), dumped) << name;
    ASSERT_EQ(back.spheres.size(), original.spheres.size());
    for (std::size_t i = 0; i < back.spheres.size(); ++i) {
      EXPECT_EQ(back.spheres[i].center, original.spheres[i].center);
      EXPECT_EQ(back.spheres[i].radius, original.spheres[i].radius);
    }
    // The same picture, pixel for pixel, at a small size.
    scene a = original, b = back;
    for (scene* s : {&a, &b}) {
      s->render.width = 48;
      s->render.spp = std::min(s->render.spp, 2);
    }
    EXPECT_EQ(test::cpu_image(a).rgb, test::cpu_image(b).rgb) << name;
  }
}

// A moving sphere and a camera's shutter are read as written, dumped the same (a sphere that
// does not move and an instant's shutter stay unsaid), and a sphere's center at time 1 is
// center1 exactly.
TEST(SceneFile, MovingSpheresAndShuttersRoundTrip) {
  const std::string text =
      R"({"camera":{"lookfrom":[0,0,3],"lookat":[0,0,0],"shutter":[0.25,0.75]},)"
      R"("materials":{"m":{"type":"normal"}},"spheres":[)"
      R"({"center":[0,0,0],"center1":[1,0.1,0],"radius":0.5,"material":"m"},)"
      R"({"center":[0,-100,0],"radius":99,"material":"m"}]})";
  const scene s = parse_scene_json(text, "moving.json");
  const camera_pose& pose = main_camera(s).pose;
  EXPECT_EQ(pose.shutter_open, 0.25);
  EXPECT_EQ(pose.shutter_close, 0.75);
  ASSERT_TRUE(s.spheres[0].center1.has_value());
  EXPECT_EQ(s.spheres[0].center_at(1), point3(1, 0.1, 0));
  EXPECT_EQ(s.spheres[0].center_at(0.5), point3(0.5, 0.05, 0));
  EXPECT_FALSE(s.spheres[1].center1.has_value());
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("\"shutter\": [0.25,0.75]"), std::string::npos) << dumped;
  EXPECT_NE(dumped.find("\"center\":[0.0,0.0,0.0],\"center1\":[1.0,0.1,0.0]"), std::string::npos)
      << dumped;
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "again.json")), dumped);
  const std::string still = dump_scene_json(builtin_scene("book-final"));
  EXPECT_EQ(still.find("center1"), std::string::npos);
  EXPECT_EQ(still.find("shutter"), std::string::npos);
}

// Quads, boxes and triangles, placed by transforms: read as the book builds them, written
// placed, and read back the same.
TEST(SceneFile, QuadsBoxesTrianglesAndTransformsRoundTrip) {
  const std::string text =
      R"({"materials":{"m":{"type":"normal"}},)"
      R"("spheres":[{"center":[1,0,0],"radius":0.5,"material":"m",)"
      R"("transform":{"scale":2,"rotate":{"axis":[0,0,1],"degrees":90}}}],)"
      R"("quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[0,1,0],"material":"m",)"
      R"("transform":{"scale":[2,1,1],"translate":[0,0,-3]}}],)"
      R"("boxes":[{"a":[0,0,0],"b":[1,2,3],"material":"m","transform":{"rotate":{"axis":[0,1,0],"degrees":90}}}],)"
      R"("triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"normals":[[0,0,1],[0,0.5,1],[0.5,0,1]],)"
      R"("material":"m"}]})";
  const scene s = parse_scene_json(text, "flat.json");
  ASSERT_EQ(s.spheres.size(), 1u);
  EXPECT_EQ(s.spheres[0].center, point3(0, 2, 0));  // scaled by 2, then turned about z
  EXPECT_EQ(s.spheres[0].radius, 1);
  ASSERT_EQ(s.quads.size(), 7u);  // one quad and a box's six
  EXPECT_EQ(s.quads[0].Q, point3(0, 0, -3));
  EXPECT_EQ(s.quads[0].u, vec3(2, 0, 0));
  // The box's front (z = 3 before the quarter turn about y, which takes +z to +x).
  EXPECT_EQ(s.quads[1].Q, point3(3, 0, 0));
  EXPECT_EQ(s.quads[1].u, vec3(0, 0, -1));
  ASSERT_EQ(s.triangles.size(), 1u);
  ASSERT_EQ(s.triangles[0].shading, 0);
  EXPECT_EQ(s.shading[0].normal[1], vec3(0, 0.5, 1));  // as written: the renderers normalize
  check_scene(s);
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "again.json")), dumped);
  EXPECT_EQ(dumped.find("\"transform\""), std::string::npos) << "objects are written placed";
}

// Instances: a group defined once, placed twice. Each placement appends the group's objects to
// their kinds, placed by the instance's transform: the values below are worked by hand (a
// quarter turn about z takes x to y and y to -x; a mirror in x swaps a quad's edges and a
// triangle's last two vertices, with their normals, so the front stays where it was).
TEST(SceneFile, InstancesPlaceTheirGroupsObjects) {
  const std::string text =
      R"({"materials":{"m":{"type":"normal"},"n":{"type":"normal"}},)"
      R"("groups":{"g":{"spheres":[{"center":[1,0,0],"radius":0.5,"material":"m"}],)"
      R"("quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[0,1,0],"material":"n"}],)"
      R"("triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"normals":[[0,0,1],[1,0,0],[0,1,0]],"material":"m"}]}},)"
      R"("instances":[{"group":"g","transform":{"scale":2,"rotate":{"axis":[0,0,1],"degrees":90},"translate":[0,0,5]}},)"
      R"({"group":"g","transform":{"scale":[-1,1,1]}}]})";
  const scene placed = parse_scene_json(text, "instances.json");
  check_scene(placed);
  ASSERT_EQ(placed.groups.size(), 1u);  // stored once
  ASSERT_EQ(placed.instances.size(), 2u);
  EXPECT_TRUE(placed.spheres.empty());
  EXPECT_EQ(placed.instances[1].placement.linear[0][0], -1);
  // Written as groups and instances (the placements as matrices), and read back the same.
  const std::string dumped = dump_scene_json(placed);
  EXPECT_NE(dumped.find("\"instances\""), std::string::npos);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "again.json")), dumped);
  // What the renderers must draw: the group's objects copied into place.
  const scene s = flatten_instances(placed);
  check_scene(s);
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_EQ(s.spheres[0].center, point3(0, 2, 5));
  EXPECT_EQ(s.spheres[0].radius, 1);
  EXPECT_EQ(s.spheres[1].center, point3(-1, 0, 0));
  EXPECT_EQ(s.spheres[1].radius, 0.5);
  ASSERT_EQ(s.quads.size(), 2u);
  EXPECT_EQ(s.quads[0].Q, point3(0, 0, 5));
  EXPECT_EQ(s.quads[0].u, vec3(0, 2, 0));
  EXPECT_EQ(s.quads[0].v, vec3(-2, 0, 0));
  EXPECT_EQ(s.quads[0].material, 1);
  EXPECT_EQ(s.quads[1].u, vec3(0, 1, 0));  // mirrored: u and v swapped
  EXPECT_EQ(s.quads[1].v, vec3(-1, 0, 0));
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.triangles[0].p[1], point3(0, 2, 5));
  EXPECT_EQ(s.triangles[0].p[2], point3(-2, 0, 5));
  EXPECT_EQ(s.triangles[1].p[1], point3(0, 1, 0));  // mirrored: the last two swapped
  EXPECT_EQ(s.triangles[1].p[2], point3(-1, 0, 0));
  ASSERT_EQ(s.shading.size(), 2u);
  ASSERT_EQ(s.triangles[1].shading, 1);
  const auto near = [](const vec3& a, const vec3& b) { return glm::length(a - b) < 1e-15; };
  EXPECT_TRUE(near(s.shading[0].normal[1], vec3(0, 1, 0)));   // (1,0,0) turned a quarter
  EXPECT_TRUE(near(s.shading[1].normal[1], vec3(0, 1, 0)));   // the second vertex's, moved
  EXPECT_TRUE(near(s.shading[1].normal[2], vec3(-1, 0, 0)));  // (1,0,0) mirrored, moved
}

// A group placed with the identity is its objects as if written at the top level.
TEST(SceneFile, AnInstanceWithoutATransformIsItsGroup) {
  const std::string objects =
      R"("spheres":[{"center":[1,2,3],"radius":0.5,"material":"m"}],)"
      R"("boxes":[{"a":[0,0,0],"b":[1,2,3],"material":"m"}],)"
      R"("triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"normals":[[0,0,1],[0,0.5,1],[0.5,0,1]],"material":"m"}])";
  const std::string m = R"({"materials":{"m":{"type":"lambertian","albedo":[0.5,0.5,0.5]}},)";
  const scene direct = parse_scene_json(m + objects + "}", "direct.json");
  const scene placed = parse_scene_json(
      m + R"("groups":{"thing":{)" + objects + R"(}},"instances":[{"group":"thing"}]})",
      "placed.json");
  EXPECT_EQ(dump_scene_json(flatten_instances(placed)), dump_scene_json(direct));
}

// A transform given as a row-major matrix places exactly as the same scale, rotation and
// translation given by parts.
TEST(SceneFile, AMatrixTransformIsTheSameAsItsParts) {
  const std::string tri = R"({"materials":{"m":{"type":"normal"}},"triangles":[{"vertices":)"
                          R"([[1,0,0],[0,2,0],[0,0,3]],"material":"m","transform":)";
  const scene parts = parse_scene_json(
      tri + R"({"scale":[2,1,1],"rotate":{"axis":[0,0,1],"degrees":90},"translate":[5,6,7]}}]})",
      "parts.json");
  // x' = -y + 5, y' = 2x + 6, z' = z + 7: rows (0 -1 0 5), (2 0 0 6), (0 0 1 7).
  const scene matrix =
      parse_scene_json(tri + R"({"matrix":[0,-1,0,5, 2,0,0,6, 0,0,1,7, 0,0,0,1]}}]})", "m.json");
  ASSERT_EQ(parts.triangles.size(), 1u);
  ASSERT_EQ(matrix.triangles.size(), 1u);
  EXPECT_EQ(matrix.triangles[0].p, parts.triangles[0].p);
  EXPECT_EQ(matrix.triangles[0].p[0], point3(5, 8, 7));
}

// Every kind of material, with the parameters it reads, written and read back the same.
TEST(SceneFile, EveryMaterialKindRoundTrips) {
  const std::string text = R"({"materials":{
    "a":{"type":"normal"},
    "b":{"type":"lambertian","albedo":[0.25,0.5,0.75]},
    "c":{"type":"metal","albedo":[0.5,0.5,0.5],"fuzz":0.125},
    "d":{"type":"dielectric","ir":1.5},
    "e":{"type":"flat","albedo":[0.8,0.3,0.1]}},"spheres":[]})";
  const scene s = parse_scene_json(text, "kinds.json");
  ASSERT_EQ(s.materials.size(), 5u);
  EXPECT_EQ(s.materials[4].m.type, material_type::flat);
  EXPECT_EQ(s.materials[4].m.albedo, color(0.8, 0.3, 0.1));
  const std::string dumped = dump_scene_json(s);
  EXPECT_NE(dumped.find("\"flat\""), std::string::npos) << dumped;
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "back.json")), dumped);
}

// Textures wherever a color goes, lamps, media and the noise seed: read as written, dumped the
// same (an image texture as its file name, relative to the scene file).
TEST(SceneFile, TexturesLampsAndMediaRoundTrip) {
  test::temp_dir dir;
  image_rgb8 img{2, 1, {255, 0, 0, 0, 0, 255}};
  write_image(img, dir.path() / "two.png");
  const std::string text = R"({"noise_seed":7,"materials":{
    "lamp":{"type":"diffuse_light","emit":[4,4,15]},
    "lit_checker":{"type":"diffuse_light","emit":{"type":"checker","scale":0.5,"even":[2,2,2],"odd":[0,0,1]}},
    "check":{"type":"lambertian","albedo":{"type":"checker","scale":0.32,"even":[0.2,0.3,0.1],"odd":[0.9,0.9,0.9]}},
    "marble":{"type":"metal","albedo":{"type":"noise","scale":4,"style":"turbulence","color":[1,0.5,0.25]},"fuzz":0.5},
    "picture":{"type":"lambertian","albedo":{"type":"image","file":"two.png"}},
    "plain":{"type":"lambertian","albedo":{"type":"solid","color":[0.5,0.5,0.5]}},
    "fog":{"type":"isotropic","albedo":[1,1,1]}},
    "spheres":[{"center":[0,0,0],"radius":1,"material":"picture"}],
    "triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"uv":[[0,0],[1,0],[0.5,1]],"material":"check"}],
    "media":[{"shape":"sphere","center":[0,0,0],"radius":2,"density":0.5,"material":"fog"},
             {"shape":"box","a":[1,2,3],"b":[0,0,0],"transform":{"rotate":{"axis":[0,1,0],"degrees":15}},"density":0.01,"material":"fog"}]})";
  const std::string file = (dir.path() / "t.json").string();
  const scene s = parse_scene_json(text, file);
  EXPECT_EQ(s.noise_seed, 7u);
  ASSERT_EQ(s.textures.size(), 4u);
  EXPECT_EQ(s.materials[0].m.type, material_type::diffuse_light);
  EXPECT_EQ(s.materials[0].m.albedo, color(4, 4, 15));  // a lamp is not clamped
  EXPECT_EQ(s.materials[1].m.texture, 0);
  EXPECT_EQ(s.textures[0].even, color(2, 2, 2));
  EXPECT_EQ(s.textures[2].style, noise_style::turbulence);
  ASSERT_EQ(s.textures[3].type, texture_type::image);
  ASSERT_TRUE(s.textures[3].image);
  EXPECT_EQ(s.textures[3].image->width, 2);
  EXPECT_EQ(s.textures[3].image->texels[0], 0xff0000ffu);  // red, linear: 255 stays 255
  EXPECT_EQ(s.textures[3].image->texels[1], 0xffff0000u);  // blue
  EXPECT_EQ(s.materials[5].m.texture, -1);                 // a solid color is the albedo
  EXPECT_EQ(s.materials[5].m.albedo, color(0.5));
  ASSERT_EQ(s.media.size(), 2u);
  EXPECT_EQ(s.media[1].lo, point3(0, 0, 0));
  EXPECT_EQ(s.media[1].hi, point3(1, 2, 3));
  ASSERT_EQ(s.shading.size(), 1u);
  EXPECT_TRUE(s.shading[0].has_uv);
  EXPECT_FALSE(s.shading[0].has_normals());
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, file)), dumped);
  EXPECT_NE(dumped.find("\"two.png\""), std::string::npos) << dumped;
}

// Lights sampling's fields: the render's sampling mode, a one-sided lamp, objects aimed at though
// they emit nothing. Read as written, dumped the same; the lights gathered are the lamp and the
// marked sphere and quad, in that order.
TEST(SceneFile, SamplingFieldsRoundTrip) {
  const std::string text = R"({"render":{"sampling":"lights","spp":4},
    "materials":{"lamp":{"type":"diffuse_light","emit":[4,4,4],"one_sided":true},
                 "glass":{"type":"dielectric","ir":1.5}},
    "spheres":[{"center":[0,0,0],"radius":1,"material":"glass","sample":true}],
    "quads":[{"Q":[0,2,0],"u":[1,0,0],"v":[0,0,1],"material":"lamp"},
             {"Q":[0,3,0],"u":[1,0,0],"v":[0,0,1],"material":"glass","sample":true},
             {"Q":[0,4,0],"u":[1,0,0],"v":[0,0,1],"material":"glass","sample":false}]})";
  const scene s = parse_scene_json(text, "s.json");
  EXPECT_EQ(s.render.sampling, sampling_mode::lights);
  EXPECT_TRUE(s.materials[0].m.one_sided);
  EXPECT_TRUE(s.spheres[0].sampled);
  EXPECT_TRUE(s.quads[1].sampled);
  EXPECT_FALSE(s.quads[2].sampled);
  const std::vector<light_record> lights = scene_lights(s);
  ASSERT_EQ(lights.size(), 3u);
  EXPECT_EQ(lights[0].kind, uint(RTVK_LIGHT_QUAD));
  EXPECT_EQ(lights[0].a, point3(0, 2, 0));
  EXPECT_EQ(lights[1].kind, uint(RTVK_LIGHT_SPHERE));
  EXPECT_EQ(lights[2].a, point3(0, 3, 0));
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "s.json")), dumped);
  EXPECT_NE(dumped.find("\"one_sided\":true"), std::string::npos) << dumped;
  EXPECT_NE(dumped.find("\"sampling\": \"lights\""), std::string::npos) << dumped;
  // The default writes nothing: files without the fields dump as before.
  const scene plain = parse_scene_json(R"({"spheres":[]})", "p.json");
  EXPECT_EQ(plain.render.sampling, sampling_mode::automatic);
  EXPECT_EQ(dump_scene_json(plain).find("sampling"), std::string::npos);
}

// Emission, its texture, alpha and culling on any kind of material: read as written, dumped
// the same, the defaults unsaid; bad values name the field.
TEST(SceneFile, SurfaceFieldsRoundTripAndBadValuesNameTheField) {
  const std::string text = R"({"materials":{
    "leaf":{"type":"lambertian","albedo":[0.2,0.6,0.1],"emission":[1,2,3],
            "emission_texture":{"type":"checker","scale":0.5,"even":[1,1,1],"odd":[0,0,0]},
            "alpha_mode":"mask","opacity":0.75,"alpha_cutoff":0.25,"cull_back":true},
    "veil":{"type":"flat","albedo":[1,1,1],"alpha_mode":"blend","opacity":0.5},
    "plain":{"type":"metal","albedo":[1,1,1]}},"spheres":[]})";
  const scene s = parse_scene_json(text, "s.json");
  const material& leaf = s.materials[0].m;
  EXPECT_EQ(leaf.emission, color(1, 2, 3));
  EXPECT_EQ(leaf.emission_texture, 0);
  EXPECT_EQ(leaf.alpha, alpha_mode::mask);
  EXPECT_EQ(leaf.opacity, 0.75);
  EXPECT_EQ(leaf.alpha_cutoff, 0.25);
  EXPECT_TRUE(leaf.cull_back);
  EXPECT_EQ(s.materials[1].m.alpha, alpha_mode::blend);
  EXPECT_EQ(material_flags(s.materials[2].m), 0u);
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "s.json")), dumped);
  EXPECT_NE(dumped.find("\"mask\""), std::string::npos) << dumped;
  // The defaults unsaid: the metal's opacity, the flat one's cutoff.
  std::size_t opacities = 0;
  for (std::size_t at = dumped.find("opacity"); at != std::string::npos;
       at = dumped.find("opacity", at + 1))
    ++opacities;
  EXPECT_EQ(opacities, 2u) << dumped;
  const struct {
    std::string field, expect;
  } cases[] = {
      {R"("emission":[-1,0,0])", "/materials/m/emission"},
      {R"("emission_texture":[1,1,1])", "/materials/m/emission_texture: expected a texture"},
      {R"("alpha_mode":"clip")",
       "/materials/m/alpha_mode: expected \"opaque\", \"mask\" or "
       "\"blend\", got \"clip\""},
      {R"("opacity":1.5)", "/materials/m/opacity"},
      {R"("alpha_cutoff":-0.1)", "/materials/m/alpha_cutoff"},
      {R"("cull_back":1)", "/materials/m/cull_back: expected true or false"},
  };
  for (const auto& c : cases) {
    const std::string json =
        R"({"materials":{"m":{"type":"flat","albedo":[1,1,1],)" + c.field + R"(}},"spheres":[]})";
    std::string e;
    try {
      parse_scene_json(json, "bad.json");
    } catch (const usage_error& x) {
      e = x.what();
    }
    EXPECT_NE(e.find(c.expect), std::string::npos) << json << "\n  gave: " << e;
  }
}

// The book's byte rule after stb_image's gamma 2.2: mid grey 128 is (128/255)^2.2 = 0.2195,
// floor(256 * 0.2195) = 56.
TEST(SceneFile, ImageTexturesAreLinearBytesAsTheBookMakesThem) {
  test::temp_dir dir;
  image_rgb8 img{1, 1, {128, 0, 255}};
  write_image(img, dir.path() / "grey.png");
  const auto t = load_texel_image(dir.path() / "grey.png", "test");
  EXPECT_EQ(t->texels[0], 0xffff0038u);
  EXPECT_EQ(linear_to_byte(1.0f), 255);
  EXPECT_EQ(linear_to_byte(-0.5f), 0);
  EXPECT_EQ(linear_to_byte(0.5f), 128);
}

// Image files that cannot be a texture: each message names the field and the file.
TEST(SceneFile, BadImageTexturesNameTheFieldAndTheFile) {
  test::temp_dir dir;
  image_rgb8 img{4, 4, std::vector<std::uint8_t>(48, 200)};
  write_image(img, dir.path() / "ok.png");
  std::string bytes = encode_png(img);
  const auto write = [&](const std::string& name, const std::string& content) {
    std::FILE* f = std::fopen((dir.path() / name).c_str(), "wb");
    std::fwrite(content.data(), 1, content.size(), f);
    std::fclose(f);
  };
  write("truncated.png", bytes.substr(0, bytes.size() / 2));
  write("text.png", "not an image at all");
  // PNG headers claiming 17000 x 17000 and 10000 x 10000 pixels: refused before anything is
  // decoded (the first past the side limit, the second past the texel limit).
  const auto be32 = [](std::uint32_t v) {
    return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
  };
  std::string huge = bytes.substr(0, 33), many = huge;
  huge.replace(16, 8, be32(17000) + be32(17000));
  many.replace(16, 8, be32(10000) + be32(10000));
  write("huge.png", huge);
  write("many.png", many);
  const auto error_for = [&](const std::string& file) {
    const std::string text =
        R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image","file":")" + file +
        R"("}}},"spheres":[]})";
    try {
      parse_scene_json(text, (dir.path() / "s.json").string());
    } catch (const usage_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_for("ok.png"), "no error");
  for (const char* file : {"missing.png", "truncated.png", "text.png", "huge.png", "many.png"}) {
    const std::string e = error_for(file);
    EXPECT_NE(e.find("/materials/m/albedo/file"), std::string::npos) << e;
    EXPECT_NE(e.find(file), std::string::npos) << e;
  }
  EXPECT_NE(error_for("huge.png").find("17000x17000 texels is past the limit (16384 a side"),
            std::string::npos)
      << error_for("huge.png");
  EXPECT_NE(error_for("many.png")
                .find("10000x10000 texels is past the limit (16384 a side, "
                      "67108864 in all)"),
            std::string::npos)
      << error_for("many.png");
  EXPECT_NE(error_for("missing.png").find("No such file"), std::string::npos)
      << error_for("missing.png");
}

TEST(SceneFile, BookFinalIsTheSameSceneEveryRun) {
  const scene a = builtin_scene("book-final"), b = builtin_scene("book-final");
  EXPECT_EQ(dump_scene_json(a), dump_scene_json(b));
  // The ground, the grid's surviving spheres, and the three big ones.
  EXPECT_GT(a.spheres.size(), 400u);
  EXPECT_LE(a.spheres.size(), 1u + 22 * 22 + 3);
  EXPECT_EQ(a.spheres.front().radius, 1000);
  EXPECT_EQ(a.spheres.back().center, point3(4, 1, 0));
}

std::string error_of(const std::string& json) {
  try {
    parse_scene_json(json, "bad.json");
  } catch (const usage_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneFile, BadFilesNameTheFileThePlaceAndTheProblem) {
  const std::string m = R"("materials":{"m":{"type":"normal"}})";
  const std::string ok_sphere = R"({"center":[0,0,-1],"radius":0.5,"material":"m"})";
  const struct {
    std::string json, expect;
  } cases[] = {
      {"{", "bad.json: parse error at line 1, column 2"},
      {"{\n  \"spheres\": [,]\n}", "line 2"},
      {"[]", "bad.json: /: expected an object"},
      {"{" + m + "}", "/: missing field \"spheres\""},
      {"{" + m + R"(,"spheres":{}})", "/spheres: expected an array"},
      {"{" + m + R"(,"spheres":[{"center":[0,0,-1],"radius":-1,"material":"m"}]})",
       "/spheres/0/radius: expected a radius > 0, got -1"},
      {"{" + m + R"(,"spheres":[)" + ok_sphere +
           R"(,{"center":[0,0,-1],"radius":0,"material":"m"}]})",
       "/spheres/1/radius: expected a radius > 0, got 0"},
      {"{" + m + R"(,"spheres":[{"center":[0,0],"radius":1,"material":"m"}]})",
       "/spheres/0/center: expected an array of 3 numbers"},
      {"{" + m + R"(,"spheres":[{"center":[0,"x",0],"radius":1,"material":"m"}]})",
       "/spheres/0/center/1: expected a number, got a string"},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":"big","material":"m"}]})",
       "/spheres/0/radius: expected a number, got a string"},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1e999,"material":"m"}]})",
       "number overflow"},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1,"material":"gold"}]})",
       "/spheres/0/material: no material named \"gold\""},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1}]})",
       "/spheres/0: missing field \"material\""},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1,"material":"m","colour":1}]})",
       "/spheres/0/colour: unknown field"},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"wood"}}},"spheres":[]})",
       "/materials/m/albedo/type: unknown texture type \"wood\""},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"checker","even":[1,1,1]}}},"spheres":[]})",
       "/materials/m/albedo: missing field \"odd\""},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"checker","scale":0,"even":[1,1,1],"odd":[0,0,0]}}},"spheres":[]})",
       "/materials/m/albedo/scale: expected a number in [1e-06, 1e+06], got 0"},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"solid","color":{"type":"solid","color":[1,1,1]}}}},"spheres":[]})",
       "/materials/m/albedo/color: expected an array of 3 numbers, got an object"},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image","file":"a.png","wrap":"tile"}}},"spheres":[]})",
       "/materials/m/albedo/wrap: expected \"clamp\", \"repeat\" or \"mirror\", got \"tile\""},
      {R"({"materials":{"m":{"type":"normal"}},"triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"uv":[[0,0],[1,0],[0,1e9]],"material":"m"}]})",
       "/triangles/0/uv/2/1: expected a number in [-1e+06, 1e+06], got 1e+09"},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"noise","style":"wavy"}}},"spheres":[]})",
       "/materials/m/albedo/style: expected \"smooth\", \"turbulence\" or \"marble\", got "
       "\"wavy\""},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"checker","even":[2,1,1],"odd":[0,0,0]}}},"spheres":[]})",
       "/materials/m/albedo/even/0: expected an albedo in [0, 1], got 2"},
      {R"({"materials":{"m":{"type":"diffuse_light","emit":[4,-1,4]}},"spheres":[]})",
       "/materials/m/emit/1: expected a color >= 0, got -1"},
      {R"({"materials":{"m":{"type":"diffuse_light","albedo":[4,1,4]}},"spheres":[]})",
       "/materials/m/albedo: unknown field"},
      {R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image"}}},"spheres":[]})",
       "/materials/m/albedo: missing field \"file\""},
      {R"({"materials":{"f":{"type":"isotropic","albedo":[1,1,1]}},"media":[{"shape":"sphere","center":[0,0,0],"radius":1,"density":-2,"material":"f"}]})",
       "/media/0/density: expected a density > 0, got -2"},
      {R"({"materials":{"f":{"type":"isotropic","albedo":[1,1,1]}},"media":[{"shape":"cone","density":1,"material":"f"}]})",
       "/media/0/shape: expected \"sphere\" or \"box\", got \"cone\""},
      {R"({"materials":{"f":{"type":"isotropic","albedo":[1,1,1]}},"media":[{"shape":"box","a":[0,0,0],"b":[1,0,1],"density":1,"material":"f"}]})",
       "/media/0/b/1: the box is flat"},
      {"{" + m +
           R"(,"media":[{"shape":"sphere","center":[0,0,0],"radius":1,"density":1,"material":"m"}]})",
       "/media/0/material: a medium scatters by an isotropic material, \"m\" is normal"},
      {R"({"noise_seed":-1,"spheres":[]})", "/noise_seed: expected an integer in [0, 4294967295]"},
      {R"({"render":{"sampling":"importance"},"spheres":[]})",
       "/render/sampling: expected \"plain\", \"lights\", \"nee\" or \"auto\", got \"importance\""},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"radius":1,"material":"m","sample":1}]})",
       "/spheres/0/sample: expected true or false, got a number"},
      {"{" + m +
           R"(,"quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[0,1,0],"material":"m","sample":"yes"}]})",
       "/quads/0/sample: expected true or false, got a string"},
      {R"({"materials":{"l":{"type":"diffuse_light","emit":[1,1,1],"one_sided":"front"}},"spheres":[]})",
       "/materials/l/one_sided: expected true or false, got a string"},
      {R"({"materials":{"l":{"type":"lambertian","albedo":[1,1,1],"one_sided":true}},"spheres":[]})",
       "/materials/l/one_sided: unknown field"},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"m","sample":true}]}},"spheres":[]})",
       "/groups/g/spheres/0/sample: lights sampling aims only at the scene's own objects, not a "
       "group's"},
      // Found by the fuzzer: a box whose sides' normals overflow float read once, then its dump
      // (the sides as quads) did not read back.
      {"{" + m + R"(,"boxes":[{"a":[0,8,0],"b":[1.3e35,2,1],"material":"m"}]})",
       "/boxes/0: side 0 of the box has no area in float (too thin or too large)"},
      {R"({"materials":{"m":{"type":"plastic"}},"spheres":[]})",
       "/materials/m/type: unknown material type \"plastic\""},
      {R"({"materials":{"m":{"type":"lambertian"}},"spheres":[]})",
       "/materials/m: missing field \"albedo\""},
      {R"({"materials":{"m":{"type":"lambertian","albedo":[2,0,0]}},"spheres":[]})",
       "/materials/m/albedo/0: expected an albedo in [0, 1], got 2"},
      {R"({"materials":{"m":{"type":"metal","albedo":[1,1,1],"fuzz":3}},"spheres":[]})",
       "/materials/m/fuzz"},
      {R"({"materials":{"m":{"type":"dielectric","ir":0}},"spheres":[]})", "/materials/m/ir"},
      {R"({"materials":{"m":{"type":"flat"}},"spheres":[]})",
       "/materials/m: missing field \"albedo\""},
      {R"({"materials":{"m":{"type":"flat","albedo":[1,1,1],"fuzz":0}},"spheres":[]})",
       "/materials/m/fuzz: unknown field"},
      {R"({"render":{"width":0},"spheres":[]})",
       "/render/width: expected an integer in [1, 65536]"},
      {R"({"render":{"spp":2.5},"spheres":[]})", "/render/spp: expected an integer, got 2.5"},
      {R"({"render":{"aspect":"16:0"},"spheres":[]})",
       "/render/aspect: invalid aspect ratio '16:0'"},
      {R"({"camera":{"vfov":200},"spheres":[]})", "/camera: vertical field of view"},
      {R"({"camera":{"projection":"fish"},"spheres":[]})",
       "/camera/projection: unknown projection \"fish\"; expected one of perspective"},
      {R"({"camera":{"projection":3},"spheres":[]})",
       "/camera/projection: expected a projection name, got a number"},
      {R"({"camera":{"fisheye_fov":400},"spheres":[]})",
       "/camera: fisheye field of view must be in (0, 360] degrees, got 400"},
      {R"({"camera":{"projection":"equirectangular","aperture":0.2},"spheres":[]})",
       "/camera: the equirectangular projection has no lens: aperture must be 0, got 0.2"},
      {R"({"cameras":{"k":{"keyframes":[{"time":0},{"time":1,"projection":"x"}]}},"spheres":[]})",
       "/cameras/k/keyframes/1/projection: unknown projection"},
      {R"({"camera":{"lookat":[0,0,0]},"spheres":[]})", "/camera: lookfrom and lookat"},
      {R"({"sky":{"zenith":[0,-1,0]},"spheres":[]})", "/sky/zenith/1"},
      {R"({"camera":{},"cameras":{"a":{}},"spheres":[]})", "/cameras: a scene has either"},
      {R"({"cameras":{},"spheres":[]})", "/cameras: expected an object of named cameras"},
      // The calibrated models' lens fields.
      {R"({"camera":{"projection":"opencv","intrinsics":[0,500,320,240]},"spheres":[]})",
       "/camera/intrinsics/0: expected a focal length fx > 0 pixels for the opencv model, got 0"},
      {R"({"camera":{"projection":"opencv-fisheye","intrinsics":[500,-1,320,240]},"spheres":[]})",
       "/camera/intrinsics/1: expected a focal length fy > 0 pixels for the opencv-fisheye "
       "model, got -1"},
      {R"({"camera":{"projection":"cylindrical","intrinsics":[100,0,320,240]},"spheres":[]})",
       "/camera/intrinsics/1: expected a focal length fy > 0 pixels for the cylindrical model"},
      {R"({"camera":{"projection":"opencv","intrinsics":[500,500,320]},"spheres":[]})",
       "/camera/intrinsics: expected [fx, fy, cx, cy] in pixels, got an array of 3"},
      {R"({"camera":{"intrinsics":{"fx":1}},"spheres":[]})",
       "/camera/intrinsics: expected [fx, fy, cx, cy] in pixels, got an object"},
      {R"({"camera":{"projection":"opencv","intrinsics":[500,500,"c",240]},"spheres":[]})",
       "/camera/intrinsics/2: expected a number, got a string"},
      {R"({"camera":{"projection":"opencv"},"spheres":[]})",
       "/camera: the opencv model needs \"intrinsics\": [fx, fy, cx, cy] in pixels"},
      {R"({"camera":{"distortion":[1,2,3,4,5,6,7,8,9]},"spheres":[]})",
       "/camera/distortion: expected 1 to 8 coefficients, got an array of 9"},
      {R"({"camera":{"distortion":[]},"spheres":[]})",
       "/camera/distortion: expected 1 to 8 coefficients, got an array of 0"},
      {R"({"camera":{"distortion":[0.1,null]},"spheres":[]})",
       "/camera/distortion/1: expected a number, got a null"},
      {R"({"camera":{"calibration_size":[640]},"spheres":[]})",
       "/camera/calibration_size: expected [width, height] in pixels, got an array"},
      {R"({"camera":{"calibration_size":[640,0]},"spheres":[]})",
       "/camera/calibration_size/1: expected an integer in [1, 65536], got 0"},
      {R"({"camera":{"calibration_size":[640.5,480]},"spheres":[]})",
       "/camera/calibration_size/0: expected an integer, got 640.5"},
      {R"({"camera":{"image_circle":-1},"spheres":[]})",
       "/camera/image_circle: expected a radius >= 0 pixels (0: none), got -1"},
      {R"({"camera":{"rolling_shutter":{"readout":-0.1}},"spheres":[]})",
       "/camera/rolling_shutter/readout: expected the readout time >= 0 seconds, got -0.1"},
      {R"({"camera":{"rolling_shutter":{"direction":"sideways","readout":1}},"spheres":[]})",
       "/camera/rolling_shutter/direction: expected \"top-down\" or \"bottom-up\", got "
       "\"sideways\""},
      {R"({"camera":{"rolling_shutter":{"direction":"top-down"}},"spheres":[]})",
       "/camera/rolling_shutter: missing field \"readout\""},
      {R"({"camera":{"rolling_shutter":{"readout":1,"speed":2}},"spheres":[]})",
       "/camera/rolling_shutter/speed: unknown field"},
      {R"({"camera":{"rolling_shutter":0.1},"spheres":[]})",
       "/camera/rolling_shutter: expected an object, got a number"},
      {R"({"camera":{"projection":"opencv","intrinsics":[500,500,319.5,239.5],"distortion":[-1],)"
       R"("calibration_size":[640,480]},"spheres":[]})",
       "/camera/distortion: the opencv distortion -1,0,0,0,0,0,0,0 is not invertible over the "
       "image"},
      {R"({"camera":{"projection":"cylindrical","aperture":0.1},"spheres":[]})",
       "/camera: the cylindrical projection has no lens: aperture must be 0, got 0.1"},
      {R"({"cameras":{"k":{"keyframes":[{"time":0,"projection":"opencv","intrinsics":[1,1,0,0]},)"
       R"({"time":1,"projection":"opencv"}]}},"spheres":[]})",
       "/cameras/k/keyframes/1: the opencv model needs \"intrinsics\""},
      {R"({"cameras":{"a b":{}},"spheres":[]})", "/cameras/a b: camera names may use"},
      {R"({"cameras":{"all":{}},"spheres":[]})", "/cameras/all: camera names"},
      {R"({"cameras":{"a":{"orbit":{"period":0}}},"spheres":[]})",
       "/cameras/a/orbit/period: expected seconds per turn > 0, got 0"},
      {R"({"cameras":{"a":{"orbit":{"speed":1}}},"spheres":[]})",
       "/cameras/a/orbit/speed: unknown field"},
      {R"({"cameras":{"a":{"keyframes":[]}},"spheres":[]})",
       "/cameras/a/keyframes: expected a non-empty array"},
      {R"({"cameras":{"a":{"keyframes":[{"lookfrom":[0,0,1]}]}},"spheres":[]})",
       "/cameras/a/keyframes/0: missing field \"time\""},
      {R"({"cameras":{"a":{"keyframes":[{"time":1},{"time":1}]}},"spheres":[]})",
       "/cameras/a/keyframes/1/time: expected a time after the previous keyframe's 1, got 1"},
      {R"({"cameras":{"a":{"vfov":30,"keyframes":[{"time":0}]}},"spheres":[]})",
       "/cameras/a/vfov: a camera with keyframes takes its pose from them"},
      {R"({"cameras":{"a":{"keyframes":[{"time":0,"lookat":[0,0,0]}]}},"spheres":[]})",
       "/cameras/a: keyframe 0: lookfrom and lookat are the same point"},
      {R"({"sky":{},"background":[0,0,0],"spheres":[]})",
       "/background: a scene has a sky or a background, not both"},
      {R"({"background":[0,-1,0],"spheres":[]})", "/background/1: expected a color >= 0, got -1"},
      {R"({"camera":{"shutter":[1,0]},"spheres":[]})",
       "/camera/shutter: expected open <= close, got [1, 0]"},
      {R"({"camera":{"shutter":0.5},"spheres":[]})",
       "/camera/shutter: expected [open, close] in seconds, got a number"},
      {R"({"camera":{"shutter":[0,"x"]},"spheres":[]})",
       "/camera/shutter/1: expected a number, got a string"},
      {"{" + m + R"(,"spheres":[{"center":[0,0,0],"center1":[0,1],"radius":1,"material":"m"}]})",
       "/spheres/0/center1: expected an array of 3 numbers"},
      {"{" + m + R"(,"quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[2,0,0],"material":"m"}]})",
       "/quads/0: u and v are parallel (or zero): the quad has no area"},
      {"{" + m + R"(,"quads":[{"Q":[0,0,0],"u":[1,0,0],"material":"m"}]})",
       "/quads/0: missing field \"v\""},
      {"{" + m + R"(,"quads":{}})", "/quads: expected an array, got an object"},
      {"{" + m + R"(,"instances":[{"group":"tree"}]})",
       "/instances/0/group: expected the name of a group (the scene has none), got \"tree\""},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]}},"instances":[{"group":"tree"}]})",
       "/instances/0/group: expected the name of a group (g), got \"tree\""},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]}},"instances":[{"group":3}]})",
       "/instances/0/group: expected the name of a group (g), got a number"},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]}},"instances":[{}]})",
       "/instances/0: missing field \"group\""},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"center1":[0,1,0],"radius":1,"material":"m"}]}}})",
       "/groups/g/spheres/0/center1: a group's spheres cannot move"},
      {"{" + m +
           R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]}},"instances":[{"group":"g","transform":{"scale":[1,0,1]}}]})",
       "/instances/0/transform: the transform cannot place anything: it flattens space"},
      {"{" + m + R"(,"groups":{"g":{}},"instances":[{"group":"g"}]})",
       "/groups/g: the group has no object (nothing an instance could place)"},
      {"{" + m + R"(,"groups":{"g":{"instances":[]}}})", "/groups/g/instances: unknown field"},
      {"{" + m + R"(,"groups":[]})", "/groups: expected an object of named groups, got an array"},
      {"{" + m +
           R"(,"groups":{"a/b":{"quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[2,0,0],"material":"m"}]}}})",
       "/groups/a~1b/quads/0: u and v are parallel (or zero): the quad has no area"},
      {"{" + m + R"(,"groups":{"g":{"spheres":[{"center":[0,0,0],"radius":1,"material":"x"}]}}})",
       "/groups/g/spheres/0/material: "},
      {"{" + m + R"(,"boxes":[{"a":[0,0,0],"b":[1,1,0],"material":"m"}]})",
       "/boxes/0/b/2: the box is flat: a and b share this coordinate"},
      {"{" + m + R"(,"triangles":[{"vertices":[[0,0,0],[1,0,0]],"material":"m"}]})",
       "/triangles/0/vertices: expected an array of 3 points"},
      {"{" + m +
           R"(,"triangles":[{"vertices":[[0,0,0],[1,0,0],[0,1,0]],"normals":[[0,0,1],[0,0,0],[0,0,1]],"material":"m"}]})",
       "/triangles/0/normals/1: expected a nonzero normal"},
      {"{" + m +
           R"(,"quads":[{"Q":[0,0,0],"u":[1,0,0],"v":[0,1,0],"material":"m","transform":{"scale":[1,0,1]}}]})",
       "/quads/0/transform: the transform cannot place anything: it flattens space"},
      {"{" + m +
           R"(,"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"m","transform":{"rotate":{"axis":[0,0,0],"degrees":3}}}]})",
       "/boxes/0/transform/rotate/axis: expected a nonzero finite axis"},
      {"{" + m + R"(,"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"m","transform":{"shear":1}}]})",
       "/boxes/0/transform/shear: unknown field"},
      {"{" + m +
           R"(,"spheres":[{"center":[0,0,0],"radius":1,"material":"m","transform":{"scale":[1,2,1]}}]})",
       "/spheres/0/transform: a sphere can be scaled only uniformly"},
      {"{" + m + R"(,"meshes":[{"file":"x.stl"}]})", "/meshes/0/file: \"x.stl\" is not .obj"},
      {"{" + m +
           R"(,"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"m","transform":{"matrix":[1,0,0,0,0,1,0,0,0,0,1]}}]})",
       "/boxes/0/transform/matrix: expected 12 or 16 numbers (row-major), got 11 values"},
      {"{" + m +
           R"(,"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"m","transform":{"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,1,1]}}]})",
       "/boxes/0/transform/matrix: the last row must be 0 0 0 1"},
      {"{" + m +
           R"(,"boxes":[{"a":[0,0,0],"b":[1,1,1],"material":"m","transform":{"matrix":[1,0,0,0,0,1,0,0,0,0,1,0],"scale":2}}]})",
       "/boxes/0/transform/scale: a transform is a matrix or scale, rotate and translate, not "
       "both"},
      {"{" + m + R"(,"triangles":[{"vertices":[[0,0,0],[1,1,1],[2,2,2]],"material":"m"}]})",
       "/triangles/0/vertices: the vertices are collinear: no area"},
      {"{" + m + R"(,"quads":[{"Q":[0,0,0],"u":[1e-30,0,0],"v":[0,1e-30,0],"material":"m"}]})",
       "/quads/0: u and v are parallel (or zero): the quad has no area"},
      {"{" + m + R"(,"meshes":[{"file":""}]})", "/meshes/0/file: expected a mesh file name"},
  };
  for (const auto& c : cases) {
    const std::string e = error_of(c.json);
    EXPECT_NE(e.find(c.expect), std::string::npos) << c.json << "\n  gave: " << e;
    EXPECT_EQ(e.rfind("bad.json: ", 0), 0u) << e;
  }
}

TEST(SceneFile, NamedCamerasWithPathsRoundTrip) {
  const std::string text = R"({
    "cameras": {
      "front": {"lookfrom": [0, 1, 5], "vfov": 30},
      "spin": {"lookfrom": [13, 2, 3], "lookat": [0, 0, 0], "orbit": {"period": 8}},
      "fly": {"keyframes": [{"time": 0, "lookfrom": [0, 0, 3]},
                            {"time": 2.5, "lookfrom": [3, 1, 0], "vfov": 60}]}
    },
    "spheres": []})";
  const scene s = parse_scene_json(text, "cams.json");
  ASSERT_EQ(s.cameras.size(), 3u);
  EXPECT_EQ(s.cameras[0].name, "front");  // the file's order: the first is the default
  EXPECT_EQ(s.cameras[0].path.motion, camera_motion::fixed);
  EXPECT_EQ(s.cameras[0].path.pose.vfov, 30);
  EXPECT_EQ(s.cameras[0].path.pose.lookat, point3(0, 0, -1));  // unset fields: the lesson's
  EXPECT_EQ(s.cameras[1].path.motion, camera_motion::orbit);
  EXPECT_EQ(s.cameras[1].path.orbit_period, 8);
  ASSERT_EQ(s.cameras[2].path.keyframes.size(), 2u);
  EXPECT_EQ(s.cameras[2].path.keyframes[1].time, 2.5);
  EXPECT_EQ(s.cameras[2].path.keyframes[1].pose.vfov, 60);
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "again.json")), dumped);
  EXPECT_NE(dumped.find("\"cameras\""), std::string::npos);
  // One camera named "default" is written the old way, so older files read back unchanged.
  EXPECT_NE(dump_scene_json(builtin_scene("seed")).find("\"camera\""), std::string::npos);
}

TEST(SceneFile, ProjectionsRoundTripAndPerspectiveStaysUnsaid) {
  const std::string text = R"({
    "cameras": {
      "pano": {"lookfrom": [0, 1, 0], "projection": "equirectangular"},
      "fish": {"keyframes": [{"time": 0, "projection": "fisheye-equisolid", "fisheye_fov": 200},
                             {"time": 1, "projection": "fisheye-equisolid"}]},
      "flat": {"projection": "orthographic", "aperture": 0.1}
    },
    "spheres": []})";
  const scene s = parse_scene_json(text, "proj.json");
  EXPECT_EQ(s.cameras[0].path.pose.projection, projection::equirectangular);
  EXPECT_EQ(s.cameras[1].path.keyframes[0].pose.fisheye_fov, 200);
  EXPECT_EQ(s.cameras[1].path.keyframes[1].pose.fisheye_fov, 180);  // the default
  EXPECT_EQ(s.cameras[2].path.pose.projection, projection::orthographic);
  const std::string dumped = dump_scene_json(s);
  EXPECT_EQ(dump_scene_json(parse_scene_json(dumped, "again.json")), dumped);
  EXPECT_NE(dumped.find("\"fisheye-equisolid\""), std::string::npos);
  EXPECT_EQ(dump_scene_json(builtin_scene("book-final")).find("projection"), std::string::npos);
}

// The calibrated models' lens fields are read as written and dumped only where they are not the
// defaults (the coefficients up to the last nonzero one), and read back to the same poses, bit
// for bit; a scene without them dumps as it always did.
TEST(SceneFile, CalibratedLensFieldsRoundTripExactly) {
  const std::string text = R"({
    "cameras": {
      "cv": {"projection": "opencv", "intrinsics": [512.25, 511.75, 319.125, 241.0625],
             "distortion": [-0.28, 0.07, 0.001, -0.0005, -0.01, 0.02, -0.01, 0.005],
             "calibration_size": [640, 480],
             "rolling_shutter": {"direction": "bottom-up", "readout": 0.0125}},
      "fish": {"projection": "opencv-fisheye", "intrinsics": [300, 305, 318.5, 241.5],
               "distortion": [0.05, -0.01, 0.002, -0.0003], "rolling_shutter": {"readout": 0.03}},
      "poly": {"projection": "fisheye-polynomial", "intrinsics": [0, 0, 318, 241],
               "distortion": [0, 0.004, 1e-6, -2e-9, 0, 0], "image_circle": 300},
      "cyl": {"projection": "cylindrical", "fisheye_fov": 270, "vfov": 60},
      "keys": {"keyframes": [
        {"time": 0, "projection": "opencv", "intrinsics": [400, 400, 80, 60], "distortion": [0.1]},
        {"time": 1, "projection": "opencv", "intrinsics": [400, 400, 80, 60], "lookfrom": [1, 0, 0]}]}
    },
    "spheres": []})";
  const scene s = parse_scene_json(text, "lens.json");
  const camera_pose& cv = s.cameras[0].path.pose;
  EXPECT_EQ(cv.projection, projection::opencv);
  EXPECT_EQ(cv.intrinsics.fx, 512.25);
  EXPECT_EQ(cv.intrinsics.cy, 241.0625);
  EXPECT_EQ(cv.intrinsics.k[7], 0.005);
  EXPECT_EQ(cv.intrinsics.width, 640);
  EXPECT_EQ(cv.intrinsics.height, 480);
  EXPECT_EQ(cv.readout, -0.0125);                   // bottom-up: negative
  EXPECT_EQ(s.cameras[1].path.pose.readout, 0.03);  // top-down, the default direction
  EXPECT_EQ(s.cameras[1].path.pose.intrinsics.k[4], 0);
  EXPECT_EQ(s.cameras[2].path.pose.intrinsics.radius, 300);
  EXPECT_EQ(s.cameras[2].path.pose.intrinsics.k[3], -2e-9);
  EXPECT_EQ(s.cameras[3].path.pose.intrinsics, lens_intrinsics{});
  EXPECT_EQ(s.cameras[4].path.keyframes[1].pose.intrinsics.k[0], 0);

  const std::string dumped = dump_scene_json(s);
  const scene back = parse_scene_json(dumped, "again.json");
  EXPECT_EQ(dump_scene_json(back), dumped);
  ASSERT_EQ(back.cameras.size(), s.cameras.size());
  for (std::size_t i = 0; i < s.cameras.size(); ++i) {
    EXPECT_TRUE(back.cameras[i].path.pose == s.cameras[i].path.pose) << s.cameras[i].name;
    ASSERT_EQ(back.cameras[i].path.keyframes.size(), s.cameras[i].path.keyframes.size());
    for (std::size_t k = 0; k < s.cameras[i].path.keyframes.size(); ++k)
      EXPECT_TRUE(back.cameras[i].path.keyframes[k].pose == s.cameras[i].path.keyframes[k].pose);
  }
  EXPECT_NE(dumped.find(R"("rolling_shutter": {"direction":"bottom-up","readout":0.0125})"),
            std::string::npos)
      << dumped;
  EXPECT_NE(dumped.find(R"("distortion": [0.0,0.004,1e-06,-2e-09])"), std::string::npos)
      << "the trailing zeros left unsaid: " << dumped;
  EXPECT_NE(dumped.find(R"("calibration_size": [640,480])"), std::string::npos) << dumped;
  EXPECT_NE(dumped.find(R"("image_circle": 300.0)"), std::string::npos) << dumped;
  const std::string still = dump_scene_json(builtin_scene("book-final"));
  for (const char* field :
       {"intrinsics", "distortion", "calibration_size", "image_circle", "rolling_shutter"})
    EXPECT_EQ(still.find(field), std::string::npos) << field;

  // A calibration of any shape is checked at its own size: a portrait one ten times taller than
  // wide reads (checked at 1x1 it was refused as another aspect ratio than the render's).
  const scene tall = parse_scene_json(
      R"({"camera": {"projection": "opencv", "intrinsics": [500, 500, 49.5, 499.5],)"
      R"( "calibration_size": [100, 1000]}, "spheres": []})",
      "tall.json");
  EXPECT_EQ(tall.cameras[0].path.pose.intrinsics.height, 1000);

  // Every field to the bit, through the one-line camera object rtvk view prints.
  camera_pose odd = cv;
  lens_intrinsics& l = odd.intrinsics;
  l.fx = 500 + 1.0 / 3.0;
  l.fy = 500 + 2.0 / 3.0;
  l.cx = 319.5 + 1e-3;
  l.cy = 239.5 + 0.1 + 0.2;
  l.k = {-1e-300, 0, 0, 0, 0, 0, 0, 1.0 / 7.0};
  l.radius = 0;
  odd.readout = 1.0 / 3.0;
  const std::string object = dump_camera_json(odd);
  const scene o = parse_scene_json(R"({"camera": )" + object + R"(, "spheres": []})", "cam.json");
  EXPECT_TRUE(o.cameras.at(0).path.pose == odd) << object;
}

// rtvk view prints its camera this way to be pasted into a scene file: every field, to the bit.
TEST(SceneFile, ACameraObjectReadsBackAsTheSamePose) {
  camera_pose lens;
  lens.lookfrom = {0.1, 1.0 / 3.0, -7e-5};
  lens.lookat = {2.5, -1e10, 3};
  lens.vup = {0.6, 0.8, 1e-3};
  lens.vfov = 33.333333333333336;
  lens.aperture = 0.07;
  lens.focus_dist = 12.125;
  camera_pose fisheye = lens;
  fisheye.aperture = 0;
  fisheye.projection = projection::fisheye_equisolid;
  fisheye.fisheye_fov = 271.5;
  for (const camera_pose& pose : {lens, fisheye}) {
    const std::string object = dump_camera_json(pose);
    EXPECT_EQ(object.find('\n'), std::string::npos) << "one line: " << object;
    const scene s = parse_scene_json(R"({"camera": )" + object + R"(, "spheres": []})", "cam.json");
    EXPECT_TRUE(s.cameras.at(0).path.pose == pose) << object;
  }
}

TEST(SceneFile, MissingEmptyAndFolderFiles) {
  test::temp_dir dir;
  EXPECT_THROW(load_scene_file(dir.path() / "none.json"), usage_error);
  EXPECT_THROW(load_scene_file(dir.path()), usage_error);
  std::ofstream(dir.path() / "empty.json") << "  \n";
  try {
    load_scene_file(dir.path() / "empty.json");
    FAIL();
  } catch (const usage_error& e) {
    EXPECT_NE(std::string(e.what()).find("empty scene file"), std::string::npos);
  }
}

TEST(SceneFile, AHundredThousandSpheresLoadAndRender) {
  // Rows of 317 spheres across x = -158..158, one row per unit of depth from z = -20 back.
  auto center_of = [](int i) { return point3(i % 317 - 158, 0, -20 - i / 317); };
  std::string json = R"({"render":{"gamma":1},"materials":{"m":{"type":"normal"}},"spheres":[)";
  for (int i = 0; i < 100000; ++i) {
    const point3 c = center_of(i);
    json += (i ? "," : "") + std::string(R"({"center":[)") + std::to_string(int(c.x)) + ",0," +
            std::to_string(int(c.z)) + R"(],"radius":0.4,"material":"m"})";
  }
  json += "]}";
  const scene s = parse_scene_json(json, "big.json");
  ASSERT_EQ(s.spheres.size(), 100000u);
  for (int i : {0, 158, 317, 99999}) {
    const point3 c = s.spheres[std::size_t(i)].center;
    EXPECT_EQ(c, center_of(i)) << "sphere " << i << " read as (" << c.x << ", " << c.y << ", "
                               << c.z << ")";
    EXPECT_EQ(s.spheres[std::size_t(i)].radius, 0.4) << "sphere " << i;
  }

  // 9 pixels wide at 16:9 is 5 high, so pixel (4, 2) looks through (u, v) = (4/8, 2/4) =
  // (0.5, 0.5): straight down -z, onto sphere 158 at (0, 0, -20). It is hit head on, normal
  // (0, 0, 1), shaded 0.5 * (normal + 1) = (0.5, 0.5, 1), written int(255.999 * c) = 127, 127, 255.
  scene small = s;
  small.render.width = 9;
  const image_rgb8 img = test::cpu_image(small);
  ASSERT_EQ(img.width, 9);
  ASSERT_EQ(img.height, 5);
  const std::uint8_t* center = img.pixel(4, 2);
  EXPECT_EQ(std::vector<int>(center, center + 3), (std::vector<int>{127, 127, 255}));

  // Every pixel is what the same spheres give when built in memory rather than read from text.
  scene built;
  built.materials = {{"m", material{}}};
  for (int i = 0; i < 100000; ++i) built.spheres.push_back(sphere(center_of(i), 0.4, 0));
  built.render.width = 9;
  EXPECT_EQ(img.rgb, test::cpu_image(built).rgb);
}

}  // namespace
}  // namespace rtvk

namespace rtvk {
namespace {

TEST(SpheresScene, HasNSpheresOnTheGroundEveryRun) {
  const scene a = builtin_scene("spheres:1000"), b = builtin_scene("spheres:1000");
  ASSERT_EQ(a.spheres.size(), 1001u);  // the ground and N small spheres
  EXPECT_EQ(dump_scene_json(a), dump_scene_json(b));
  for (std::size_t i = 1; i < a.spheres.size(); ++i) {
    const sphere& s = a.spheres[i];
    // Resting on the radius-1000 ground: 0.2 above its surface.
    EXPECT_NEAR(glm::length(s.center - point3(0, -1000, 0)), 1000.2, 1e-9);
    ASSERT_GE(s.material, 1);
    ASSERT_LT(std::size_t(s.material), a.materials.size());
  }
}

}  // namespace
}  // namespace rtvk
