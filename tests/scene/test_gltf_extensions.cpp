// glTF's compression extensions and cameras (host/formats/gltf_ext/): the Draco Duck is the plain
// Duck within its quantization, a meshopt Duck made here from the plain one is the same
// triangles, corrupt streams are refused by file and primitive, and a file's cameras become the
// scene's, posed as glTF poses them.
#include <gtest/gtest.h>

#include <fstream>

#include "camera.h"
#include "errors.h"
#include "gltfx_helpers.h"
#include "mesh_file.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

const std::filesystem::path data_dir = RTVK_GLTFX_DATA;  // tests/data/gltf

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary) << bytes;
}

// A mesh file's triangles with its shading (normals), every face given one gray material.
scene gltfx_load(const std::filesystem::path& file) {
  scene s;
  s.materials.push_back({"gray", {material_type::lambertian, color(0.5), 0, 1.5}});
  mesh_placement how;
  how.material = 0;
  load_mesh(s, file, how);
  return s;
}

std::string gltfx_refusal(const std::string& bytes, const std::string& kind) {
  scene s;
  try {
    load_mesh_bytes(s, bytes, kind, "m." + kind, "", {});
  } catch (const usage_error& e) {
    return e.what();
  }
  return "";
}

// The corners of b rotated to start where a's first corner is (the meshopt index codec may
// rotate a triangle, keeping its winding): the rotation, or -1 when none is within `tol`.
int rotation_of(const triangle& a, const triangle& b, double tol) {
  for (int r = 0; r < 3; ++r) {
    double err = 0;
    for (int k = 0; k < 3; ++k)
      err = std::max(err, glm::length(a.p[std::size_t(k)] - b.p[std::size_t((k + r) % 3)]));
    if (err <= tol) return r;
  }
  return -1;
}

// The Draco Duck's position quantization, read from its stream: the grid step, file units.
double draco_duck_step() {
  const std::string bytes = read_bytes(data_dir / "DuckDraco" / "Duck.bin");
  draco::DecoderBuffer in;
  in.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  decoder.SetSkipAttributeTransform(draco::GeometryAttribute::POSITION);  // keep the grid
  auto mesh = decoder.DecodeMeshFromBuffer(&in);
  if (!mesh.ok()) return 0;
  const draco::PointAttribute* pos =
      mesh.value()->GetNamedAttribute(draco::GeometryAttribute::POSITION);
  draco::AttributeQuantizationTransform q;
  if (!pos || !q.InitFromAttribute(*pos)) return 0;
  return q.range() / double((1 << q.quantization_bits()) - 1);
}

TEST(GltfDraco, TheDracoDuckIsThePlainDuckWithinItsQuantization) {
  const scene plain = gltfx_load(data_dir / "DuckDraco" / "Duck.gltf");
  const scene draco = gltfx_load(data_dir / "DuckDraco" / "DuckDraco.gltf");
  ASSERT_EQ(plain.triangles.size(), 4212u);
  ASSERT_EQ(draco.triangles.size(), plain.triangles.size());
  // A corner is within half a grid diagonal of the plain one, after the node's 0.01 scale (and
  // float rounding); 0 would mean the stream's grid was not found.
  const double step = draco_duck_step(), bound = 0.01 * step * std::sqrt(3.0) / 2 + 1e-6;
  ASSERT_GT(step, 0);
  std::printf("Draco Duck: grid step %.4g file units, corners within %.3g\n", step, bound);
  // Draco reorders faces and vertices: each Draco triangle is matched to the plain one nearest
  // it, corner to corner (among those of a centroid within 3 bounds).
  const auto centroid = [](const triangle& t) { return (t.p[0] + t.p[1] + t.p[2]) / 3.0; };
  std::vector<bool> taken(plain.triangles.size());
  double worst = 0;
  for (const triangle& d : draco.triangles) {
    std::size_t best = 0;
    double best_error = INFINITY;
    int best_r = -1;
    for (std::size_t i = 0; i < plain.triangles.size(); ++i) {
      const triangle& p = plain.triangles[i];
      if (glm::length(centroid(p) - centroid(d)) > 3 * bound) continue;
      for (int r = 0; r < 3; ++r) {
        double e = 0;
        for (int k = 0; k < 3; ++k)
          e = std::max(e, glm::length(p.p[std::size_t(k)] - d.p[std::size_t((k + r) % 3)]));
        if (e < best_error) best_error = e, best = i, best_r = r;
      }
    }
    ASSERT_LE(best_error, bound) << "no plain triangle near Draco's at " << centroid(d).x << ", "
                                 << centroid(d).y << ", " << centroid(d).z;
    ASSERT_GE(best_r, 0);
    EXPECT_FALSE(taken[best]);
    taken[best] = true;
    worst = std::max(worst, best_error);
    EXPECT_GE(d.shading, 0);  // its normals and texture coordinates came along
  }
  EXPECT_GT(worst, 0);  // quantized, not the plain file read twice
  std::printf("Draco Duck: worst corner %.3g from the plain Duck's\n", worst);
}

TEST(GltfDraco, AStreamThatDoesNotDecodeIsRefusedByFileAndPrimitive) {
  const test::indexed_mesh m = test::cube_sphere(2, 1.0);
  const std::string good = test::draco_glb(m);
  scene s;
  load_mesh_bytes(s, good, "glb", "m.glb", "", {});
  EXPECT_EQ(s.triangles.size(), m.faces.size());
  // The stream's bytes after its header garbled; then its magic word broken.
  std::string garbled = good;
  const std::size_t bin_start = garbled.find("DRACO");
  ASSERT_NE(bin_start, std::string::npos);
  for (std::size_t i = bin_start + 12; i < garbled.size(); ++i) garbled[i] = char(0xA5 ^ i);
  const std::string why = gltfx_refusal(garbled, "glb");
  EXPECT_EQ(why.rfind("m.glb: mesh 0 primitive 0: KHR_draco_mesh_compression: ", 0), 0u) << why;
  std::string cut = good;
  cut.replace(bin_start, 5, "DRACX");
  EXPECT_NE(gltfx_refusal(cut, "glb").find("the Draco stream does not decode"), std::string::npos)
      << gltfx_refusal(cut, "glb");
}

// A dumped scene names the Draco Duck's texture as "DuckDraco.gltf#images/0": reading it back
// parses the Draco file again, for the image alone.
TEST(GltfDraco, ADumpedDracoSceneReadsItsImageBack) {
  const test::temp_dir dir;
  for (const char* f : {"DuckDraco.gltf", "Duck.bin", "DuckCM.png"})
    std::filesystem::copy_file(data_dir / "DuckDraco" / f, dir.path() / f);
  const std::string dumped = dump_scene_json(mesh_scene(dir.path() / "DuckDraco.gltf"));
  EXPECT_NE(dumped.find("DuckDraco.gltf#images/0"), std::string::npos);
  write_bytes(dir.path() / "d.json", dumped);
  EXPECT_EQ(dump_scene_json(load_scene_file(dir.path() / "d.json")), dumped);
}

// The plain Duck re-encoded with EXT_meshopt_compression: positions with the EXPONENTIAL
// filter, normals OCTAHEDRAL in 16-bit shorts, texture coordinates unfiltered, indices in the
// TRIANGLES codec; buffer 0 the fallback without data, buffer 1 the streams.
nlohmann::json meshopt_duck(std::string& bin) {
  nlohmann::json doc = nlohmann::json::parse(read_bytes(data_dir / "DuckDraco" / "Duck.gltf"));
  const std::string plain = read_bytes(data_dir / "DuckDraco" / "Duck0.bin");
  const auto bytes_of = [&](int accessor, std::size_t element) {
    const nlohmann::json& a = doc["accessors"][accessor];
    const nlohmann::json& v = doc["bufferViews"][a["bufferView"].get<int>()];
    return plain.substr(v.value("byteOffset", 0) + a.value("byteOffset", 0),
                        a["count"].get<std::size_t>() * element);
  };
  const std::size_t n = 2399, corners = 12636;
  std::string idx;  // the 16-bit indices as 32-bit ones
  const std::string idx16 = bytes_of(0, 2);
  for (std::size_t i = 0; i < corners; ++i) {
    std::uint16_t v16;
    std::memcpy(&v16, idx16.data() + 2 * i, 2);
    const std::uint32_t v = v16;
    idx.append(reinterpret_cast<const char*>(&v), 4);
  }
  std::string normals(n * 8, '\0'), positions(n * 12, '\0');
  std::vector<float> n4(n * 4), p3(n * 3);
  const std::string nrm = bytes_of(1, 12), pos = bytes_of(2, 12);
  for (std::size_t i = 0; i < n; ++i) std::memcpy(&n4[4 * i], nrm.data() + 12 * i, 12);
  std::memcpy(p3.data(), pos.data(), pos.size());
  meshopt_encodeFilterOct(normals.data(), n, 8, 16, n4.data());
  meshopt_encodeFilterExp(positions.data(), n, 12, 24, p3.data());
  std::size_t fallback = 0;
  doc["bufferViews"] = {
      test::meshopt_view(idx, corners, 4, "TRIANGLES", "", bin, fallback),
      test::meshopt_view(normals, n, 8, "ATTRIBUTES", "OCTAHEDRAL", bin, fallback),
      test::meshopt_view(positions, n, 12, "ATTRIBUTES", "EXPONENTIAL", bin, fallback),
      test::meshopt_view(bytes_of(3, 8), n, 8, "ATTRIBUTES", "", bin, fallback)};
  doc["accessors"][0] = {
      {"bufferView", 0}, {"componentType", 5125}, {"count", corners}, {"type", "SCALAR"}};
  doc["accessors"][1] = {{"bufferView", 1},
                         {"componentType", 5122},
                         {"normalized", true},
                         {"count", n},
                         {"type", "VEC3"}};
  doc["accessors"][2]["bufferView"] = 2;
  doc["accessors"][2]["byteOffset"] = 0;
  doc["accessors"][3]["bufferView"] = 3;
  doc["buffers"] = {{{"byteLength", fallback},
                     {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}},
                    {{"byteLength", bin.size()}, {"uri", "duck.meshopt.bin"}}};
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  for (const char* unused : {"images", "textures", "samplers", "materials"}) doc.erase(unused);
  doc["meshes"][0]["primitives"][0].erase("material");
  return doc;
}

TEST(GltfMeshopt, AMeshoptDuckMadeFromThePlainOneIsTheSameTriangles) {
  const test::temp_dir dir;
  std::string bin;
  nlohmann::json doc = meshopt_duck(bin);
  write_bytes(dir.path() / "duck.meshopt.bin", bin);
  write_bytes(dir.path() / "duck.gltf", doc.dump());
  // The .glb: the streams its BIN chunk (buffer 1 without uri), the fallback after it.
  nlohmann::json glb = doc;
  glb["buffers"] = {{{"byteLength", bin.size()}}, doc["buffers"][0]};
  for (nlohmann::json& v : glb["bufferViews"]) {
    v["buffer"] = 1;
    v["extensions"]["EXT_meshopt_compression"]["buffer"] = 0;
  }
  write_bytes(dir.path() / "duck.glb", test::glb_of(glb.dump(), bin));
  const scene plain = gltfx_load(data_dir / "DuckDraco" / "Duck.gltf");
  std::printf("meshopt Duck: %zu bytes of streams for the plain Duck's %zu\n", bin.size(),
              std::size_t(102040));
  for (const char* name : {"duck.gltf", "duck.glb"}) {
    const scene m = gltfx_load(dir.path() / name);
    ASSERT_EQ(m.triangles.size(), plain.triangles.size()) << name;
    double worst_p = 0, worst_n = 0;
    for (std::size_t f = 0; f < m.triangles.size(); ++f) {
      const triangle &a = plain.triangles[f], &b = m.triangles[f];
      const int r = rotation_of(a, b, 1e-5);
      ASSERT_GE(r, 0) << name << " triangle " << f;
      for (int k = 0; k < 3; ++k) {
        const std::size_t j = std::size_t((k + r) % 3);
        worst_p = std::max(worst_p, glm::length(a.p[std::size_t(k)] - b.p[j]));
        worst_n = std::max(
            worst_n, glm::length(plain.shading[std::size_t(a.shading)].normal[std::size_t(k)] -
                                 m.shading[std::size_t(b.shading)].normal[j]));
        EXPECT_EQ(plain.shading[std::size_t(a.shading)].uv[std::size_t(k)],
                  m.shading[std::size_t(b.shading)].uv[j]);
      }
    }
    EXPECT_LT(worst_n, 1e-4) << name;  // 16-bit octahedral
    std::printf("%s: worst corner %.3g, worst normal %.3g\n", name, worst_p, worst_n);
  }
}

TEST(GltfMeshopt, AStreamThatDoesNotDecodeIsRefusedByView) {
  std::string bin;
  nlohmann::json doc = meshopt_duck(bin);
  doc["buffers"][1]["uri"] = "data:application/octet-stream;base64," + test::base64(bin);
  EXPECT_EQ(gltfx_refusal(doc.dump(), "gltf"), "");  // embedded, it loads
  nlohmann::json quaternion = doc;
  quaternion["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["filter"] = "QUATERNION";
  EXPECT_EQ(gltfx_refusal(quaternion.dump(), "gltf"),
            "m.gltf: bufferViews 2: EXT_meshopt_compression: QUATERNION needs byteStride 8");
  std::string garbled(bin.size(), '\x5a');  // every stream garbled
  doc["buffers"][1]["uri"] = "data:application/octet-stream;base64," + test::base64(garbled);
  const std::string why = gltfx_refusal(doc.dump(), "gltf");
  EXPECT_EQ(why.rfind("m.gltf: bufferViews 0: EXT_meshopt_compression: the TRIANGLES stream does "
                      "not decode",
                      0),
            0u)
      << why;
}

// The Cameras sample: a unit square turned 45 degrees about x, seen by a perspective camera
// (yfov 0.7, aspect 1) and an orthographic one (xmag = ymag = 1), both at (0.5, 0.5, 3)
// looking down -z: the first sees the square as a trapezoid, the second as a rectangle half the
// view wide.
TEST(GltfCameras, TheCamerasSampleGivesTheFilesTwoCamerasThenTheFramingOne) {
  const scene s = mesh_scene(data_dir / "Cameras" / "Cameras.gltf");
  ASSERT_EQ(s.cameras.size(), 3u);
  EXPECT_EQ(s.cameras[0].name, "camera0");
  EXPECT_EQ(s.cameras[1].name, "camera1");
  EXPECT_EQ(s.cameras[2].name, "default");  // the framing camera, still there
  EXPECT_EQ(s.render.aspect, 1.0);
  const camera_pose& p = s.cameras[0].path.pose;
  EXPECT_EQ(p.projection, projection::perspective);
  EXPECT_EQ(p.lookfrom, point3(0.5, 0.5, 3));
  EXPECT_EQ(p.lookat, point3(0.5, 0.5, 2));
  EXPECT_EQ(p.vup, vec3(0, 1, 0));
  EXPECT_NEAR(p.vfov, 0.7 * 180 / M_PI, 1e-12);
  // The orthographic camera's rays: parallel to -z, leaving x = 0.5 + (s - 0.5) * 2 xmag, so
  // the square's edges x = 0 and 1 are at s = 0.25 and 0.75.
  const camera ortho(s.cameras[1].path.pose, s.render.aspect, 101);
  EXPECT_EQ(ortho.projection(), projection::orthographic);
  for (const double at : {0.25, 0.75}) {
    const ray r = ortho.get_ray(at, 0.5);
    EXPECT_NEAR(r.origin.x, at == 0.25 ? 0.0 : 1.0, 1e-12);
    EXPECT_NEAR(r.origin.z, 3.0, 1e-12);
    EXPECT_NEAR(glm::length(glm::normalize(r.direction) - vec3(0, 0, -1)), 0, 1e-12);
  }
  EXPECT_NEAR(ortho.get_ray(0.5, 1.0).origin.y, 1.5, 1e-12);  // ymag 1 above the center
  // The perspective camera's top row looks yfov / 2 above its axis.
  const camera persp(p, s.render.aspect, 101);
  const vec3 top = glm::normalize(persp.get_ray(0.5, 1.0).direction);
  EXPECT_NEAR(std::atan2(top.y, -top.z), 0.35, 1e-12);
}

// The Draco Duck's camera, a child of a node scaling by 0.01, posed by its world matrix: the
// eye at 0.01 times the camera node's translation, looking down the node's -z (its third column
// negated), its up the second column.
TEST(GltfCameras, TheDucksCameraIsPosedByItsWorldTransform) {
  const scene s = mesh_scene(data_dir / "DuckDraco" / "DuckDraco.gltf");
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].name, "camera0");
  EXPECT_EQ(s.render.aspect, 1.5);
  const camera_pose& p = s.cameras[0].path.pose;
  const point3 eye(4.001130065917969, 4.632640075683594, -4.310780334472656);
  EXPECT_NEAR(glm::length(p.lookfrom - eye), 0, 1e-6);
  const vec3 ahead =
      -glm::normalize(vec3(0.5364750623703003, 0.6211478114128113, -0.571287989616394));
  EXPECT_NEAR(glm::length(p.lookat - p.lookfrom - ahead), 0, 1e-6);
  EXPECT_NEAR(glm::length(glm::normalize(p.vup) -
                          glm::normalize(
                              vec3(-0.4252049028873444, 0.7836934328079224, 0.4527972936630249))),
              0, 1e-6);
  EXPECT_NEAR(p.vfov, 0.6605925559997559 * 180 / M_PI, 1e-9);
}

TEST(GltfCameras, NamesAreUsableAndUniqueAndBadLensesAreRefused) {
  const test::temp_dir dir;
  nlohmann::json doc = nlohmann::json::parse(test::gltf_json(test::cube_sphere(1, 1.0)));
  const nlohmann::json persp = {{"type", "perspective"},
                                {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}};
  doc["cameras"] = {persp, persp, persp, persp};
  doc["cameras"][0]["name"] = "front view";
  doc["cameras"][1]["name"] = "front view";
  doc["cameras"][2]["name"] = "default";
  doc["nodes"] = {{{"mesh", 0}},
                  {{"camera", 0}, {"translation", {0, 0, 5}}},
                  {{"camera", 1}, {"translation", {0, 0, 6}}},
                  {{"camera", 2}, {"translation", {0, 0, 7}}},
                  {{"camera", 3}, {"name", "all"}, {"translation", {0, 0, 8}}}};
  doc["scenes"][0]["nodes"] = {0, 1, 2, 3, 4};
  write_bytes(dir.path() / "c.gltf", doc.dump());
  const scene s = mesh_scene(dir.path() / "c.gltf");
  std::vector<std::string> names;
  for (const named_camera& c : s.cameras) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"front_view", "front_view-2", "default-2", "all_",
                                             "default"}));
  EXPECT_EQ(s.render.aspect, 16.0 / 9.0);  // no aspectRatio: the render's own
  doc["cameras"][1]["perspective"]["yfov"] = 3.5;
  write_bytes(dir.path() / "c.gltf", doc.dump());
  try {
    mesh_scene(dir.path() / "c.gltf");
    ADD_FAILURE() << "a yfov of 3.5 radians was taken";
  } catch (const usage_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
                  (dir.path() / "c.gltf").string() + ": node 2 camera 1: yfov 3.5", 0),
              0u)
        << e.what();
  }
}

}  // namespace
}  // namespace rtvk
