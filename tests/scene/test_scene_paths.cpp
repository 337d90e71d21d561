// A scene file's paths confined to its folder (docs/farm.md): textures, meshes and the files
// meshes name may not reach out of it by "..", an absolute path or a symlink, unless the caller
// allows any path or names a wider root.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "errors.h"
#include "image_io.h"
#include "mesh_file.h"
#include "scene_file.h"
#include "temp_dir.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;

// root/outside.png, outside.obj, outside.mtl, outside.bin; root/scenes/ (the scene file's
// folder) with inside.png, link.png -> ../outside.png, link-in.png -> inside.png and sub/; root/scenes2/other.png, a sibling
// whose name begins with the scene folder's.
class ScenePaths : public ::testing::Test {
 protected:
  void SetUp() override {
    scenes = dir.path() / "scenes";
    fs::create_directories(scenes);
    fs::create_directories(dir.path() / "scenes2");
    fs::create_directories(scenes / "sub");
    const image_rgb8 img{1, 1, {255, 0, 0}};
    for (const fs::path& p : {dir.path() / "outside.png", scenes / "inside.png",
                              dir.path() / "scenes2" / "other.png", other.path() / "far.png"})
      write_image(img, p);
    fs::create_symlink("../outside.png", scenes / "link.png");
    fs::create_symlink("inside.png", scenes / "link-in.png");
    write(dir.path() / "outside.obj", triangle_obj);
    write(dir.path() / "outside.mtl", "newmtl red\nKd 1 0 0\n");
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write(dir.path() / "outside.bin", std::string(reinterpret_cast<const char*>(corners), 36));
  }

  static void write(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
  }

  // The scene file scenes/s.json whose material's image texture is `file`.
  std::string textured(const std::string& file) const {
    return R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image","file":")" + file +
           R"("}}},"spheres":[{"center":[0,0,0],"radius":1,"material":"m"}]})";
  }

  // The message parsing `text` as scenes/s.json gives, or "" when it is read.
  std::string error_of(const std::string& text, const file_access& access = {}) const {
    try {
      parse_scene_json(text, (scenes / "s.json").string(), access);
    } catch (const usage_error& e) {
      return e.what();
    }
    return "";
  }

  static constexpr const char* triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  test::temp_dir dir, other;
  fs::path scenes;
};

TEST_F(ScenePaths, FilesInTheScenesFolderAreRead) {
  for (const char* file : {"inside.png", "./inside.png", "sub/../inside.png", "link-in.png"})
    EXPECT_EQ(error_of(textured(file)), "") << file;
  EXPECT_EQ(error_of(textured((scenes / "inside.png").string())), "") << "absolute, inside";
}

TEST_F(ScenePaths, ATextureUpTheTreeIsRefusedNamingTheFieldAndThePath) {
  const std::string e = error_of(textured("../outside.png"));
  EXPECT_NE(e.find("s.json: /materials/m/albedo/file: \"../outside.png\" is outside "),
            std::string::npos)
      << e;
  EXPECT_NE(e.find(fs::weakly_canonical(scenes).string()), std::string::npos) << e;
  EXPECT_NE(e.find("--allow-any-path"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
  EXPECT_NE(error_of(textured("sub/../../outside.png")), "");
}

TEST_F(ScenePaths, AnAbsolutePathOutsideIsRefused) {
  const std::string far = (other.path() / "far.png").string();
  EXPECT_NE(error_of(textured(far)).find("\"" + far + "\" is outside"), std::string::npos)
      << error_of(textured(far));
}

TEST_F(ScenePaths, ASymlinkPointingOutIsRefused) {
  EXPECT_NE(error_of(textured("link.png")).find("\"link.png\" is outside"), std::string::npos)
      << error_of(textured("link.png"));
}

// Folders are compared by whole names: root/scenes2 is not inside root/scenes.
TEST_F(ScenePaths, ASiblingWhoseNameBeginsLikeTheFolderIsOutside) {
  EXPECT_NE(error_of(textured("../scenes2/other.png")), "");
  EXPECT_NE(error_of(textured((dir.path() / "scenes2" / "other.png").string())), "");
}

TEST_F(ScenePaths, AllowAnyPathReadsThemAll) {
  const file_access any{.any_path = true, .root = {}};
  for (const std::string& file : {std::string("../outside.png"), std::string("link.png"),
                                  (other.path() / "far.png").string()})
    EXPECT_EQ(error_of(textured(file), any), "") << file;
}

TEST_F(ScenePaths, ASceneRootAllowsItsWholeFolderAndNothingElse) {
  const file_access root{.any_path = false, .root = dir.path()};
  EXPECT_EQ(error_of(textured("../outside.png"), root), "");
  EXPECT_EQ(error_of(textured("link.png"), root), "");
  EXPECT_EQ(error_of(textured("../scenes2/other.png"), root), "");
  const std::string e = error_of(textured((other.path() / "far.png").string()), root);
  EXPECT_NE(e.find(fs::weakly_canonical(dir.path()).string() + ", the folder"), std::string::npos)
      << e;
}

// A mesh file, an OBJ's MTL, a glTF's external buffer and a dumped glTF image (FILE#images/N)
// are files a scene reads too.
TEST_F(ScenePaths, MeshesAndTheFilesTheyNameAreConfinedToo) {
  const std::string m = R"("materials":{"m":{"type":"lambertian","albedo":[1,1,1]}})";
  EXPECT_NE(error_of("{" + m + R"(,"meshes":[{"file":"../outside.obj"}]})")
                .find("/meshes/0/file: \"../outside.obj\" is outside"),
            std::string::npos);
  write(scenes / "lib.obj", std::string("mtllib ../outside.mtl\n") + triangle_obj);
  const std::string mtl = error_of("{" + m + R"(,"meshes":[{"file":"lib.obj"}]})");
  EXPECT_NE(mtl.find("lib.obj: mtllib: \"../outside.mtl\" is outside"), std::string::npos) << mtl;
  write(scenes / "buf.gltf",
        R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../outside.bin","byteLength":36}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,)"
        R"("componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],)"
        R"("scenes":[{"nodes":[0]}]})");
  const std::string buf = error_of("{" + m + R"(,"meshes":[{"file":"buf.gltf"}]})");
  EXPECT_NE(buf.find("buf.gltf: \""), std::string::npos) << buf;
  EXPECT_NE(buf.find("outside.bin\" is outside"), std::string::npos) << buf;
  EXPECT_NE(error_of(textured("../x.gltf#images/0")).find("\"../x.gltf#images/0\" is outside"),
            std::string::npos);
  const file_access any{.any_path = true, .root = {}};
  EXPECT_EQ(error_of("{" + m + R"(,"meshes":[{"file":"../outside.obj"}]})", any), "");
  EXPECT_EQ(error_of("{" + m + R"(,"meshes":[{"file":"lib.obj"}]})", any), "");
  EXPECT_EQ(error_of("{" + m + R"(,"meshes":[{"file":"buf.gltf"}]})", any), "");
}

// `rtvk render --scene m.obj`: the mesh's own files stay in its folder.
TEST_F(ScenePaths, AMeshReadAloneIsConfinedToItsFolder) {
  write(scenes / "lib.obj", std::string("mtllib ../outside.mtl\n") + triangle_obj);
  EXPECT_THROW(mesh_scene(scenes / "lib.obj"), usage_error);
  EXPECT_EQ(mesh_scene(scenes / "lib.obj", {.any_path = true, .root = {}}).triangles.size(), 1u);
}

}  // namespace
}  // namespace rtvk
