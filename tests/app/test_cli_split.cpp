// The executable's many-camera, animation and split-render paths: files named from -o patterns,
// pieces written as OpenEXR and merged, and bad requests refused with exit 2 and no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gpu_fixture.h"
#include "process.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;
using test::slurp;

std::vector<std::string> validated_gpu_args(std::vector<std::string> args) {
  args.insert(args.end(), {"--backend", "gpu", "--validate"});
  if (!test::test_device().empty()) args.insert(args.end(), {"--device", test::test_device()});
  return args;
}

// Four cameras over the materials scene, one of them keyframed.
fs::path write_four_camera_scene(const fs::path& dir) {
  const fs::path path = dir / "four.json";
  std::ofstream(path) << R"({
  "cameras": {
    "front": {"lookfrom": [0, 0.5, 2], "lookat": [0, 0, -1], "vfov": 50},
    "left": {"lookfrom": [-3, 1, 0], "lookat": [0, 0, -1], "vfov": 40},
    "top": {"lookfrom": [0, 4, -0.9], "lookat": [0, 0, -1], "vfov": 60},
    "dolly": {"keyframes": [{"time": 0, "lookfrom": [3, 3, 2], "lookat": [0, 0, -1], "vfov": 20},
                            {"time": 1, "lookfrom": [1, 1, 1], "lookat": [0, 0, -1], "vfov": 50}]}
  },
  "render": {"width": 48, "aspect": "3:2", "spp": 4, "max_depth": 8, "gamma": 2, "jitter": true},
  "materials": {"ground": {"type": "lambertian", "albedo": [0.8, 0.8, 0]},
                "glass": {"type": "dielectric", "ir": 1.5},
                "gold": {"type": "metal", "albedo": [0.8, 0.6, 0.2], "fuzz": 0.1}},
  "spheres": [{"center": [0, -100.5, -1], "radius": 100, "material": "ground"},
              {"center": [0, 0, -1], "radius": 0.5, "material": "glass"},
              {"center": [1, 0, -1], "radius": 0.5, "material": "gold"}]
})";
  return path;
}

class CliSplitGpu : public test::GpuTest {};

TEST_F(CliSplitGpu, AllCamerasInOneRunEachEqualTheCameraAlone) {
  test::temp_dir dir;
  const std::string scene = write_four_camera_scene(dir.path()).string();
  const auto all =
      run_rtvk(validated_gpu_args({"render", "--scene", scene, "--camera", "all", "--frames", "1",
                                   "-o", (dir.path() / "all_{camera}.png").string()}));
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_NE(all.err.find("4 views together"), std::string::npos) << all.err;
  for (const std::string name : {"front", "left", "top", "dolly"}) {
    const fs::path alone = dir.path() / ("alone_" + name + ".png");
    const auto r = run_rtvk(validated_gpu_args(
        {"render", "--scene", scene, "--camera", name, "--frames", "1", "-o", alone.string()}));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string together = slurp(dir.path() / ("all_" + name + ".png"));
    EXPECT_FALSE(together.empty()) << name;
    EXPECT_EQ(together, slurp(alone)) << name;
  }
  EXPECT_NE(slurp(dir.path() / "all_front.png"), slurp(dir.path() / "all_top.png"));
}

TEST_F(CliSplitGpu, GpuTilesMergeToTheWholeRenderAndSampleHalvesAgree) {
  test::temp_dir dir;
  auto at = [&](const std::string& f) { return (dir.path() / f).string(); };
  const std::vector<std::string> base = {"render", "--scene", "book-final", "--width", "50",
                                         "--spp",  "4",       "--depth",    "8",       "-q"};
  auto render = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return run_rtvk(validated_gpu_args(args)).status;
  };
  ASSERT_EQ(render({"-o", at("whole.exr")}), 0);
  ASSERT_EQ(render({"--region", "0,0,20,33", "-o", at("t0.exr")}), 0);
  ASSERT_EQ(render({"--region", "20,0,30,33", "-o", at("t1.exr")}), 0);
  ASSERT_EQ(render({"--samples", "0:1", "-o", at("s0.exr")}), 0);
  ASSERT_EQ(render({"--samples", "1:4", "-o", at("s1.exr")}), 0);
  ASSERT_EQ(run_rtvk({"merge", at("whole.exr"), "-o", at("whole.png")}).status, 0);
  ASSERT_EQ(run_rtvk({"merge", at("t1.exr"), at("t0.exr"), "-o", at("tiles.png")}).status, 0);
  EXPECT_EQ(slurp(at("tiles.png")), slurp(at("whole.png")));
  const auto halves = run_rtvk({"merge", at("s0.exr"), at("s1.exr"), "-o", at("halves.png")});
  ASSERT_EQ(halves.status, 0) << halves.err;
  EXPECT_NE(halves.err.find("samples 0:4"), std::string::npos) << halves.err;
  // Float sums in another order: equal to within a level almost everywhere.
  const auto cmp = run_rtvk(
      {"compare", at("halves.png"), at("whole.png"), "--tolerance", "1", "--max-share", "0.001"});
  EXPECT_EQ(cmp.status, 0) << cmp.out;
}

TEST(CliSplit, OrbitAnimationWritesNumberedFrames) {
  test::temp_dir dir;
  const auto r = run_rtvk({"render", "--scene", "book-final", "--width", "40", "--spp", "2",
                           "--depth", "6", "--orbit", "8", "--fps", "2", "--frames", "0:3", "-o",
                           (dir.path() / "frame_{frame:04}.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string f0 = slurp(dir.path() / "frame_0000.png");
  const std::string f1 = slurp(dir.path() / "frame_0001.png");
  const std::string f2 = slurp(dir.path() / "frame_0002.png");
  EXPECT_FALSE(f0.empty());
  EXPECT_NE(f0, f1);
  EXPECT_NE(f1, f2);
  EXPECT_FALSE(fs::exists(dir.path() / "frame_0003.png"));  // A:B stops before B
  // Frame 0 of an orbit is the camera's own pose.
  const auto still = run_rtvk({"render", "--scene", "book-final", "--width", "40", "--spp", "2",
                               "--depth", "6", "-o", (dir.path() / "still.png").string()});
  ASSERT_EQ(still.status, 0);
  EXPECT_EQ(slurp(dir.path() / "still.png"), f0);
}

TEST(CliSplit, CpuSplitsMergeAndMergeRefusesMismatches) {
  test::temp_dir dir;
  auto at = [&](const std::string& f) { return (dir.path() / f).string(); };
  auto render = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render", "--scene", "materials", "--width",
                                     "40",     "--spp",   "4",         "-q"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_rtvk(args);
  };
  ASSERT_EQ(render({"-o", at("whole.exr")}).status, 0);
  ASSERT_EQ(render({"--region", "0,0,40,10", "-o", at("top.exr")}).status, 0);
  ASSERT_EQ(render({"--region", "0,10,40,12", "-o", at("bottom.exr")}).status, 0);
  ASSERT_EQ(run_rtvk({"merge", at("whole.exr"), "-o", at("whole.ppm")}).status, 0);
  ASSERT_EQ(run_rtvk({"merge", at("top.exr"), at("bottom.exr"), "-o", at("tiles.ppm")}).status, 0);
  EXPECT_EQ(slurp(at("tiles.ppm")), slurp(at("whole.ppm")));
  // A merged .exr merges again, and the result is unchanged.
  ASSERT_EQ(run_rtvk({"merge", at("top.exr"), at("bottom.exr"), "-o", at("again.exr")}).status, 0);
  ASSERT_EQ(run_rtvk({"merge", at("again.exr"), "-o", at("again.ppm")}).status, 0);
  EXPECT_EQ(slurp(at("again.ppm")), slurp(at("whole.ppm")));

  ASSERT_EQ(render({"--seed", "7", "--region", "0,10,40,12", "-o", at("other.exr")}).status, 0);
  std::ofstream(at("not.exr")) << "P3\n1 1\n255\n0 0 0\n";
  const std::vector<std::pair<std::vector<std::string>, std::string>> refusals = {
      {{at("top.exr")}, "is in none of the parts"},
      {{at("top.exr"), at("whole.exr")}, "hold the same samples"},
      {{at("top.exr"), at("other.exr")}, "rendered from a different scene"},
      {{at("not.exr")}, "not.exr"},
      {{at("missing.exr")}, "missing.exr"},
  };
  for (const auto& [parts, expect] : refusals) {
    std::vector<std::string> args = {"merge"};
    args.insert(args.end(), parts.begin(), parts.end());
    args.insert(args.end(), {"-o", at("refused.png")});
    const auto r = run_rtvk(args);
    EXPECT_EQ(r.status, 2) << expect << ": " << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(at("refused.png"))) << expect;
  }
}

TEST(CliSplit, BadRequestsExit2WithoutFiles) {
  test::temp_dir dir;
  const std::string scene = write_four_camera_scene(dir.path()).string();
  const std::string out = (dir.path() / "out").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--camera", "nope", "-o", out + ".png"}, "--camera nope"},
      {{"--camera", "all", "-o", out + ".png"}, "put {camera} in the name"},
      {{"--frames", "0:3", "-o", out + "_{camera}.png"}, "put {frame} or {frame:04}"},
      {{"--frames", "3:1", "-o", out + ".png"}, "--frames: '3:1'"},
      {{"--frames", "x", "-o", out + ".png"}, "--frames: 'x'"},
      {{"--fps", "0", "-o", out + ".png"}, "--fps: 0"},
      {{"--region", "40,0,9,4", "-o", out + ".png"}, "--region 40,0,9,4"},
      {{"--region", "1,2,3", "-o", out + ".png"}, "--region: '1,2,3'"},
      {{"--samples", "0:5", "-o", out + ".png"}, "--samples: '0:5'"},
      {{"-o", out + "_{take}.png"}, "unknown placeholder {take}"},
      {{"--camera", "dolly", "--orbit", "4", "-o", out + ".png"}, "--orbit"},
      {{"--camera", "dolly", "--vfov", "30", "-o", out + ".png"}, "moves by keyframes"},
  };
  for (const auto& [args, expect] : cases) {
    std::vector<std::string> full = {"render", "--scene", scene};
    full.insert(full.end(), args.begin(), args.end());
    const auto r = run_rtvk(full);
    EXPECT_EQ(r.status, 2) << expect << ": " << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << r.err;
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) files += e.path() != scene;
    EXPECT_EQ(files, 0) << expect;
  }
}

TEST(CliSplit, PiecesOfOtherProjectionsDoNotMerge) {
  test::temp_dir dir;
  const auto at = [&](const std::string& f) { return (dir.path() / f).string(); };
  const auto piece = [&](const std::string& model, const std::string& samples,
                         const std::string& out) {
    return run_rtvk({"render", "--scene", "materials", "--width", "32", "--spp", "4", "--backend",
                     "cpu", "--projection", model, "--aperture", "0", "--samples", samples, "-o",
                     at(out), "-q"})
        .status;
  };
  ASSERT_EQ(piece("fisheye-equidistant", "0:2", "a.exr"), 0);
  ASSERT_EQ(piece("fisheye-equidistant", "2:4", "b.exr"), 0);
  ASSERT_EQ(piece("equirectangular", "2:4", "c.exr"), 0);
  EXPECT_EQ(run_rtvk({"merge", at("a.exr"), at("b.exr"), "-o", at("ab.png")}).status, 0);
  const auto mixed = run_rtvk({"merge", at("a.exr"), at("c.exr"), "-o", at("ac.png")});
  EXPECT_EQ(mixed.status, 2) << mixed.err;
  EXPECT_NE(mixed.err.find("fingerprint"), std::string::npos) << mixed.err;
  EXPECT_FALSE(fs::exists(at("ac.png")));
}

// Pieces of small CPU renders in a folder of their own, and whether two of them merge (refused
// only for their fingerprints).
class pieces {
 public:
  std::string at(const std::string& f) const { return (dir_.path() / f).string(); }
  // Samples `samples` of a 24-pixel-wide render of `scene` at 2 spp into `out`: the exit status.
  int piece(const std::string& scene, const std::string& samples, const std::string& out,
            const std::vector<std::string>& more = {}) const {
    std::vector<std::string> args{"render", "--scene", scene,       "--width", "24",
                                  "--spp",  "2",       "--backend", "cpu",     "--samples",
                                  samples,  "-o",      at(out),     "-q"};
    args.insert(args.end(), more.begin(), more.end());
    return run_rtvk(args).status;
  }
  bool merges(const std::string& a, const std::string& b) const {
    const auto r = run_rtvk({"merge", at(a), at(b), "-o", at("m.png")});
    EXPECT_TRUE(r.status == 0 || r.err.find("fingerprint") != std::string::npos) << r.err;
    return r.status == 0;
  }

 private:
  test::temp_dir dir_;
};

// Where spheres move, the instants a piece sampled are part of what it is: pieces of another
// shutter, or of another frame, are refused (they once merged into a silently wrong image).
// Where nothing moves the time changes nothing, and frames' pieces merge as before.
TEST(CliSplit, PiecesOfOtherInstantsDoNotMergeWhereSpheresMove) {
  const pieces p;
  ASSERT_EQ(p.piece("bouncing-spheres", "0:1", "a.exr"), 0);
  ASSERT_EQ(p.piece("bouncing-spheres", "1:2", "b.exr"), 0);
  ASSERT_EQ(p.piece("bouncing-spheres", "1:2", "half.exr", {"--shutter", "0:0.5"}), 0);
  ASSERT_EQ(p.piece("bouncing-spheres", "1:2", "later.exr", {"--frames", "1"}), 0);
  EXPECT_TRUE(p.merges("a.exr", "b.exr"));
  EXPECT_FALSE(p.merges("a.exr", "half.exr"));
  EXPECT_FALSE(p.merges("a.exr", "later.exr"));
  // Another motion (only center1 differs) is another scene.
  const auto moving_to = [&](const std::string& file, const std::string& center1) {
    std::ofstream(p.at(file)) << R"({"spheres": [{"center": [0, 0, -1], "center1": )" << center1
                              << R"(, "radius": 0.5, "material": "m"}],
        "materials": {"m": {"type": "normal"}}, "camera": {"shutter": [0, 1]}})";
    return p.at(file);
  };
  ASSERT_EQ(p.piece(moving_to("right.json", "[1, 0, -1]"), "0:1", "right.exr"), 0);
  ASSERT_EQ(p.piece(moving_to("left.json", "[-1, 0, -1]"), "1:2", "left.exr"), 0);
  ASSERT_EQ(p.piece(moving_to("right2.json", "[1, 0, -1]"), "1:2", "right2.exr"), 0);
  EXPECT_FALSE(p.merges("right.exr", "left.exr"));
  EXPECT_TRUE(p.merges("right.exr", "right2.exr"));
  ASSERT_EQ(p.piece("book-final", "0:1", "still0.exr"), 0);
  ASSERT_EQ(p.piece("book-final", "1:2", "still1.exr", {"--frames", "1"}), 0);
  EXPECT_TRUE(p.merges("still0.exr", "still1.exr"));
}

// Quads and meshes are part of what a piece is: pieces of a mesh scene merge into the image a
// whole render draws, and a piece of the same scene with one vertex or quad moved is refused.
TEST(CliSplit, PiecesOfMeshScenesMergeOnlyWithTheSameGeometry) {
  const pieces p;
  const auto write_mesh = [&](const std::string& file, const std::string& apex) {
    std::ofstream(p.at(file)) << "v -1 -1 -2\nv 1 -1 -2\n"
                              << apex << "\nv 0 -1 -3\nf 1 2 3\nf 2 4 3\nf 4 1 3\n";
  };
  const auto write_scene = [&](const std::string& file, const std::string& mesh,
                               const std::string& quad_y) {
    std::ofstream(p.at(file))
        << R"({"materials": {"m": {"type": "lambertian", "albedo": [0.5, 0.5, 0.5]}},
        "quads": [{"Q": [-3, )"
        << quad_y << R"(, -4], "u": [6, 0, 0], "v": [0, 0, 4], "material": "m"}],
        "meshes": [{"file": ")"
        << mesh << R"(", "material": "m"}]})";
  };
  write_mesh("tri.obj", "v 0 0.5 -2.5");
  write_mesh("tri2.obj", "v 0 0.6 -2.5");
  write_scene("a.json", "tri.obj", "-1");
  write_scene("b.json", "tri2.obj", "-1");   // one vertex moved
  write_scene("c.json", "tri.obj", "-1.1");  // the quad moved
  ASSERT_EQ(p.piece(p.at("a.json"), "0:1", "a0.exr"), 0);
  ASSERT_EQ(p.piece(p.at("a.json"), "1:2", "a1.exr"), 0);
  ASSERT_EQ(p.piece(p.at("b.json"), "1:2", "b1.exr"), 0);
  ASSERT_EQ(p.piece(p.at("c.json"), "1:2", "c1.exr"), 0);
  EXPECT_TRUE(p.merges("a0.exr", "a1.exr"));
  EXPECT_EQ(slurp(p.at("m.png")), [&] {
    const auto whole = run_rtvk({"render", "--scene", p.at("a.json"), "--width", "24", "--spp", "2",
                                 "--backend", "cpu", "-o", p.at("whole.png"), "-q"});
    EXPECT_EQ(whole.status, 0) << whole.err;
    return slurp(p.at("whole.png"));
  }()) << "the merged pieces are the whole render";
  EXPECT_FALSE(p.merges("a0.exr", "b1.exr"));
  EXPECT_FALSE(p.merges("a0.exr", "c1.exr"));
}

TEST(CliSplit, PiecesOfOtherScenesOrSettingsDoNotMerge) {
  const pieces p;
  std::ofstream(p.at("one.json")) << R"({"spheres": [{"center": [0, 0, -1], "radius": 0.5,
      "material": "m"}], "materials": {"m": {"type": "normal"}}})";
  std::ofstream(p.at("moved.json")) << R"({"spheres": [{"center": [0, 0, -1.0000001],
      "radius": 0.5, "material": "m"}], "materials": {"m": {"type": "normal"}}})";
  ASSERT_EQ(p.piece("spheres:50", "0:1", "a.exr"), 0);
  ASSERT_EQ(p.piece("spheres:50", "1:2", "b.exr"), 0);
  ASSERT_EQ(p.piece("spheres:51", "1:2", "c.exr"), 0);
  ASSERT_EQ(p.piece("spheres:50", "1:2", "d.exr", {"--seed", "7"}), 0);
  ASSERT_EQ(p.piece(p.at("one.json"), "0:1", "e.exr"), 0);
  ASSERT_EQ(p.piece(p.at("moved.json"), "1:2", "f.exr"), 0);
  EXPECT_TRUE(p.merges("a.exr", "b.exr"));
  EXPECT_FALSE(p.merges("a.exr", "c.exr")) << "another sphere";
  EXPECT_FALSE(p.merges("a.exr", "d.exr")) << "another seed";
  EXPECT_FALSE(p.merges("e.exr", "f.exr")) << "a sphere moved by 1e-7";
}

}  // namespace
}  // namespace rtvk
