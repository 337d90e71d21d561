// Inputs that once hung rtvk, crashed it or merged silently, on the real executable: each is
// refused at once with exit 2, a message naming the flag or file, and no output file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "image_io.h"
#include "partial_image.h"
#include "process.h"
#include "scene_file.h"
#include "version.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;
using test::run_rtvk_within;
using test::slurp;

constexpr std::chrono::seconds prompt{20};  // "at once", with room for a loaded machine

int file_count(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

// Overwrites the bytes that follow `key` in the file at `path` with `value`.
void patch(const fs::path& path, const std::string& key, const std::string& value) {
  std::string bytes = slurp(path);
  const auto at = bytes.find(key);
  ASSERT_NE(at, std::string::npos) << key;
  bytes.replace(at + key.size(), value.size(), value);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::string box2i(int x0, int y0, int x1, int y1) {
  const int v[4] = {x0, y0, x1, y1};
  return std::string(reinterpret_cast<const char*>(v), sizeof v);
}

TEST(CliHardening, MalformedOutputPatternsAreRefusedAtOnce) {
  test::temp_dir dir;
  for (const std::string name : {"a_{frame", "a}b.png", "a{}.png", "a{{frame}}.png",
                                 "x{frame{camera}}.png", "x_{frame:0}.png", "{camera"}) {
    const std::string pattern = (dir.path() / name).string();
    const auto r = run_rtvk_within(prompt, {"render", "--scene", "seed", "-o", pattern});
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find("--output '" + pattern + "': "), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_EQ(file_count(dir.path()), 0) << name;
  }
}

TEST(CliHardening, InputsThatAreNotRegularFilesAreRefused) {
  test::temp_dir dir;
  const fs::path fifo = dir.path() / "pipe.json", folder = dir.path() / "folder.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_directory(folder);
  const std::string png = (dir.path() / "seed.png").string(), out = (dir.path() / "out.png");
  ASSERT_EQ(run_rtvk({"render", "--scene", "seed", "--width", "8", "-q", "-o", png}).status, 0);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"render", "--scene", "/dev/zero", "-o", out},
       "/dev/zero: is a character device, not a "
       "regular scene file"},
      {{"render", "--scene", fifo, "-o", out}, "pipe.json: is a FIFO (named pipe), not a regular"},
      {{"render", "--scene", folder, "-o", out}, "folder.json: is a folder, not a regular"},
      {{"compare", "/dev/zero", png}, "/dev/zero: is a character device, not a regular image"},
      {{"compare", png, fifo}, "pipe.json: is a FIFO (named pipe), not a regular image file"},
      {{"merge", fifo, "-o", out}, "pipe.json: is a FIFO (named pipe), not a regular OpenEXR"},
      {{"merge", "/dev/zero", "-o", out}, "/dev/zero: is a character device"},
      {{"merge", folder, "-o", out}, "folder.json: is a folder, not a regular OpenEXR piece"},
  };
  for (const auto& [args, expect] : cases) {
    const auto r = run_rtvk_within(prompt, args);
    EXPECT_EQ(r.status, 2) << expect << ": " << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << expect;
  }
}

TEST(CliHardening, ASceneFileAboveTheLimitIsRefusedUnread) {
  test::temp_dir dir;
  const fs::path big = dir.path() / "big.json";
  std::ofstream(big) << "{";
  fs::resize_file(big, max_scene_file_bytes + 1);  // sparse: no disk space, no time to write
  const auto r = run_rtvk_within(
      prompt, {"render", "--scene", big.string(), "-o", (dir.path() / "out.png").string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("big.json: scene file is larger than the 1 GiB rtvk reads"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out.png"));
}

TEST(CliHardening, AForgedPieceClaimingAHugeWindowIsRefusedBeforeItsPixelsAreAllocated) {
  test::temp_dir dir;
  const fs::path piece = dir.path() / "piece.exr", out = dir.path() / "out.png";
  ASSERT_EQ(run_rtvk({"render", "--scene", "seed", "--width", "8", "-q", "-o", piece}).status, 0);
  // 60000x60000 float RGB is 40 GiB.
  patch(piece, std::string("dataWindow\0box2i\0", 17) + std::string("\x10\0\0\0", 4),
        box2i(0, 0, 59999, 59999));
  patch(piece, std::string("displayWindow\0box2i\0", 20) + std::string("\x10\0\0\0", 4),
        box2i(0, 0, 59999, 59999));
  // Room for the line offset table the claimed window has (3750 chunks of 16 rows), so that
  // OpenEXR opens the file and the header's claim is what rtvk has to judge.
  std::ofstream(piece, std::ios::binary | std::ios::app) << std::string(3750 * 8, '\0');
  const auto r = run_rtvk_within(prompt, {"merge", piece, "-o", out});
  EXPECT_EQ(r.status, 2) << r.err;
  // Where less than twice the claim is available (any machine but the largest), the header alone
  // is refused; elsewhere the pixels are read in bands and the first missing one ends the read.
  // Either way the claim is never allocated.
  const bool refused_by_header =
      r.err.find("piece.exr: its data window of 60000x60000 pixels needs 40.2331 GiB; ") !=
      std::string::npos;
  const bool refused_by_read =
      r.err.find("piece.exr: cannot read as OpenEXR: ") != std::string::npos;
  EXPECT_TRUE(refused_by_header || refused_by_read) << r.err;
  EXPECT_LT(r.max_rss_kib, 512 * 1024) << "KiB at the peak";
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliHardening, PiecesOfDifferentVersionsMergeOnlyWhenAllowed) {
  test::temp_dir dir;
  auto at = [&](const std::string& f) { return (dir.path() / f).string(); };
  for (const std::string range : {"0:2", "2:4"})
    ASSERT_EQ(run_rtvk({"render", "--scene", "materials", "--width", "16", "--spp", "4",
                        "--samples", range, "-q", "-o", at("s" + range.substr(0, 1) + ".exr")})
                  .status,
              0);
  const partial_image first = read_partial_exr(at("s0.exr"));
  EXPECT_EQ(first.version, version_string);
  EXPECT_EQ(first.shader.size(), 16u) << "the render shader's SPIR-V, hashed";
  EXPECT_EQ(read_partial_exr(at("s2.exr")).shader, first.shader);
  ASSERT_EQ(run_rtvk({"merge", at("s0.exr"), at("s2.exr"), "-o", at("same.png")}).status, 0);

  const std::string other(std::strlen(version_string), '9');
  // name, type, size (4 bytes, little-endian), then the string's bytes
  patch(at("s2.exr"),
        std::string("rtvk.version\0string\0", 20) + char(other.size()) + std::string(3, '\0'),
        other);
  const auto refused = run_rtvk({"merge", at("s0.exr"), at("s2.exr"), "-o", at("mixed.png")});
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find("s2.exr: rendered by rtvk " + other + " with shader " + first.shader +
                             " but "),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(at("mixed.png")));
  const auto allowed = run_rtvk(
      {"merge", "--allow-mixed-versions", at("s0.exr"), at("s2.exr"), "-o", at("mixed.png")});
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  EXPECT_EQ(slurp(at("mixed.png")), slurp(at("same.png")));
}

// A scene file naming a texture outside its folder (a farm's users' files, docs/farm.md): every
// command that reads it refuses it with the field and the path, unless a flag allows it.
TEST(CliHardening, AScenesFilesOutsideItsFolderAreRefusedUnlessAllowed) {
  test::temp_dir dir;
  fs::create_directories(dir.path() / "scenes");
  write_image(image_rgb8{1, 1, {255, 0, 0}}, dir.path() / "outside.png");
  const std::string scene = (dir.path() / "scenes" / "s.json").string();
  std::ofstream(scene) << R"({"materials":{"m":{"type":"lambertian","albedo":{"type":"image",)"
                          R"("file":"../outside.png"}}},)"
                          R"("spheres":[{"center":[0,0,-1],"radius":0.5,"material":"m"}]})";
  const std::string out = (dir.path() / "out.ppm").string();
  const std::vector<std::string> render = {"render", "--scene", scene, "--width", "8",
                                           "--spp",  "1",       "-q",  "-o",      out};
  const auto with = [&](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.begin() + 1, more.begin(), more.end());
    return run_rtvk_within(prompt, args);
  };
  for (const auto& args : {render, std::vector<std::string>{"scene", "dump", scene}}) {
    const auto r = run_rtvk_within(prompt, args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("/materials/m/albedo/file: \"../outside.png\" is outside"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  EXPECT_EQ(with(render, {"--allow-any-path"}).status, 0);
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);
  EXPECT_EQ(with(render, {"--scene-root", dir.path().string()}).status, 0);
  EXPECT_TRUE(fs::exists(out));
  fs::remove(out);
  EXPECT_EQ(run_rtvk_within(prompt, {"scene", "dump", "--allow-any-path", scene}).status, 0);
  const auto missing = with(render, {"--scene-root", (dir.path() / "nope").string()});
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--scene-root"), std::string::npos) << missing.err;
  EXPECT_EQ(with(render, {"--allow-any-path", "--scene-root", dir.path().string()}).status, 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace rtvk
