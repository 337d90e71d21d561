// The real executable on the GPU: render, compare, devices, and the no-device paths.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fault_layer.h"
#include "gpu_fixture.h"
#include "image_io.h"
#include "process.h"

namespace rtvk {
namespace {

namespace fs = std::filesystem;
using test::run_rtvk;

// The GPU flags for the device under test.
std::vector<std::string> gpu_args(std::vector<std::string> args) {
  if (!test::test_device().empty()) args.insert(args.end(), {"--device", test::test_device()});
  return args;
}

class CliGpu : public test::GpuTest {};

TEST_F(CliGpu, ValidatedGpuRenderEqualsTheCpuReference) {
  test::temp_dir dir;
  const auto gpu_ppm = (dir.path() / "gpu.ppm").string(),
             cpu_ppm = (dir.path() / "cpu.ppm").string();
  const auto g = run_rtvk(
      gpu_args({"render", "--scene", "seed", "--backend", "gpu", "--validate", "-o", gpu_ppm}));
  ASSERT_EQ(g.status, 0) << g.err;
  EXPECT_EQ(g.err.find("validation:"), std::string::npos) << g.err;
  EXPECT_NE(g.err.find("on gpu"), std::string::npos) << g.err;
  ASSERT_EQ(run_rtvk({"render", "--backend", "cpu", "-o", cpu_ppm}).status, 0);

  const auto same = run_rtvk({"compare", gpu_ppm, cpu_ppm});
  EXPECT_EQ(same.status, 0) << same.out;
  EXPECT_NE(same.out.find("alike"), std::string::npos) << same.out;

  // An upside-down copy of the reference must be reported as different.
  image_rgb8 flipped = read_image(cpu_ppm);
  const image_rgb8 original = flipped;
  for (int y = 0; y < flipped.height; ++y)
    std::copy_n(original.pixel(0, original.height - 1 - y), original.width * 3,
                flipped.rgb.begin() + std::ptrdiff_t(y) * original.width * 3);
  const auto flipped_png = (dir.path() / "flipped.png").string();
  write_image(flipped, flipped_png);
  const auto diff_png = (dir.path() / "diff.png").string();
  const auto differ = run_rtvk({"compare", gpu_ppm, flipped_png, "--diff", diff_png});
  EXPECT_EQ(differ.status, 1) << differ.out;
  EXPECT_NE(differ.out.find("different"), std::string::npos) << differ.out;
  EXPECT_TRUE(fs::exists(diff_png));
}

// Before anything is measured a dispatch is a short calibration, and its time sizes the ones
// after it (pacer.h). book-final's 485 spheres tested by every ray (--accel none) at 600x400:
// when the first dispatch was allowed 2^26 iterations, the whole image was one band, its starved
// samples' budgets grew fourfold within it, and its submission took over 4 s on this 2-core
// lavapipe: --gpu-timeout 2 failed with VK_TIMEOUT (seen). Now every submission stays inside it
// (a third of a second at most here), and the image is the BVH render's.
TEST_F(CliGpu, TheFirstSubmissionsHoldATwoSecondTimeout) {
  test::temp_dir dir;
  const auto bvh = (dir.path() / "bvh.png").string(), scan = (dir.path() / "scan.png").string();
  const std::vector<std::string> common{"render", "--scene", "book-final", "--width", "600",
                                        "--spp",  "1",       "--backend",  "gpu"};
  auto args = common;
  args.insert(args.end(), {"-o", bvh});
  ASSERT_EQ(run_rtvk(gpu_args(args)).status, 0);
  args = common;
  args.insert(args.end(), {"--accel", "none", "--gpu-timeout", "2", "-o", scan});
  const auto r = run_rtvk(gpu_args(args));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(read_image(bvh).rgb == read_image(scan).rgb) << "the image changed";
}

// lavapipe compiles a pipeline's shaders inside the first submission that runs them: a cold
// compile (Mesa's cache off, a fresh rtvk cache) of the seed render took 3 to 7 s on 2 cores of
// Mesa 22.3, and over two minutes for PBR on Mesa 25, past the default --gpu-timeout of 120 s.
// It is not a hung device: --gpu-timeout 0.5 failed with VK_TIMEOUT here before that first run
// got its allowance (context.h's note_first_run). The later submissions still hold to it, and
// the image is the CPU's (--backend both).
TEST_F(CliGpu, AColdShaderCompileIsNotTakenForAHungDevice) {
  test::temp_dir dir;
  const auto out = (dir.path() / "both.png").string();
  const auto r =
      run_rtvk(gpu_args({"render", "--scene", "seed", "--width", "64", "--spp", "4", "--backend",
                         "both", "--gpu-timeout", "0.5", "-o", out}),
               {"MESA_SHADER_CACHE_DISABLE=true", "XDG_CACHE_HOME=" + dir.path().string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(CliGpu, BackendBothChecksGpuAgainstCpu) {
  test::temp_dir dir;
  const auto out = (dir.path() / "both.png").string();
  const auto r = run_rtvk(gpu_args({"render", "--backend", "both", "--width", "160", "-o", out}));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("): alike"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST_F(CliGpu, ValidateByEnvironmentVariable) {
  test::temp_dir dir;
  const auto args = gpu_args({"render", "--backend", "gpu", "-o", (dir.path() / "a.png").string()});
  const auto r = run_rtvk(args, {"RTVK_VALIDATE=1"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("validation:"), std::string::npos) << r.err;
  // A clean run looks the same with validation off, so prove the variable asks for the layer:
  // with the loader pointed at a folder of no layers, RTVK_VALIDATE=1 must fail for want of it,
  // and the same run without it must not.
  const std::string no_layers = "VK_LAYER_PATH=" + (dir.path() / "no-layers").string();
  const auto without_layer = run_rtvk(args, {"RTVK_VALIDATE=1", no_layers});
  EXPECT_EQ(without_layer.status, 1) << without_layer.err;
  EXPECT_NE(without_layer.err.find("VK_LAYER_KHRONOS_validation is not installed"),
            std::string::npos)
      << without_layer.err;
  const auto unvalidated = run_rtvk(args, {"RTVK_VALIDATE=0", no_layers});
  EXPECT_EQ(unvalidated.status, 0) << unvalidated.err;
}

TEST_F(CliGpu, DevicesListsAndMarksThePick) {
  const auto r = run_rtvk({"devices"});
  ASSERT_EQ(r.status, 0) << r.err;
  // The device under test is the pick (RTVK_DEVICE), wherever the loader lists it.
  EXPECT_NE(r.out.find("* " + std::to_string(gpu().device().index) + ": "), std::string::npos)
      << r.out;
  if (test::test_device().empty()) {
    EXPECT_NE(r.out.find("llvmpipe"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[cpu]"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Vulkan 1."), std::string::npos) << r.out;
  }
}

// What the device under test offers, read by the test itself from the extension list (not
// through gpu::has_device_extension, part of the code under test).
bool lists_extension(VkPhysicalDevice dev, const char* name) {
  std::uint32_t n = 0;
  vkEnumerateDeviceExtensionProperties(dev, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateDeviceExtensionProperties(dev, nullptr, &n, exts.data());
  for (const auto& e : exts)
    if (std::string(e.extensionName) == name) return true;
  return false;
}

TEST_F(CliGpu, DevicesShowTheDriverItsVersionAndWhatItOffersOfRayTracing) {
  const auto text = run_rtvk({"devices"});
  ASSERT_EQ(text.status, 0) << text.err;
  const auto json = run_rtvk({"devices", "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  const nlohmann::json devices = nlohmann::json::parse(json.out);
  const auto& d = gpu().device();
  ASSERT_LT(d.index, devices.size()) << json.out;
  const auto& mine = devices[d.index];
  EXPECT_EQ(mine["name"], d.name) << json.out;
  EXPECT_TRUE(mine["chosen"].get<bool>()) << "RTVK_DEVICE picks it: " << json.out;
  const bool queries = lists_extension(d.handle, VK_KHR_RAY_QUERY_EXTENSION_NAME);
  const bool pipelines = lists_extension(d.handle, VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME);
  EXPECT_EQ(mine["ray_queries"].get<bool>(), queries) << json.out;
  EXPECT_EQ(mine["ray_tracing_pipelines"].get<bool>(), pipelines) << json.out;
  EXPECT_NE(text.out.find(std::string("ray queries: ") + (queries ? "yes" : "no") +
                          ", ray-tracing pipelines: " + (pipelines ? "yes" : "no")),
            std::string::npos)
      << text.out;
  if (test::test_device().empty()) {               // lavapipe: its ID, its names, Mesa's version
    EXPECT_EQ(mine["driver_id"], 13) << json.out;  // VK_DRIVER_ID_MESA_LLVMPIPE
    EXPECT_EQ(mine["driver"], "lavapipe") << json.out;
    EXPECT_EQ(mine["driver_name"], "llvmpipe") << json.out;
    EXPECT_EQ(mine["driver_info"].get<std::string>().rfind("Mesa ", 0), 0u) << json.out;
    EXPECT_NE(text.out.find("driver lavapipe (llvmpipe), Mesa "), std::string::npos) << text.out;
  }
}

// --device takes the driver's names and version as well as the device's name, and RTVK_DEVICE
// stands in for it.
TEST_F(CliGpu, DeviceByDriverNameOrVersionOrFromRtvkDevice) {
  if (!test::test_device().empty()) GTEST_SKIP() << "names lavapipe's driver";
  test::temp_dir dir;
  const auto out = (dir.path() / "x.png").string();
  // "lavapipe" is in no name the driver reports: only its driver ID says it. (Matching the
  // driver's version is DeviceSelector's: on a machine with a Mesa GPU driver it would pick that.)
  for (const char* sel : {"lavapipe", "LLVMPIPE"}) {
    const auto r = run_rtvk({"render", "--backend", "gpu", "--device", sel, "-o", out});
    EXPECT_EQ(r.status, 0) << sel << ": " << r.err;
    EXPECT_NE(r.err.find("on gpu (llvmpipe"), std::string::npos) << r.err;
  }
  fs::remove(out);
  const auto env = run_rtvk({"render", "--backend", "gpu", "-o", out}, {"RTVK_DEVICE=no-such-gpu"});
  EXPECT_EQ(env.status, 2) << env.err;
  EXPECT_NE(env.err.find("RTVK_DEVICE: 'no-such-gpu' matches no Vulkan device"), std::string::npos)
      << env.err;
  EXPECT_NE(env.err.find("] driver lavapipe (llvmpipe), Mesa "), std::string::npos) << env.err;
  EXPECT_FALSE(fs::exists(out));
  const auto flag_wins = run_rtvk({"render", "--backend", "gpu", "--device", "lavapipe", "-o", out},
                                  {"RTVK_DEVICE=no-such-gpu"});
  EXPECT_EQ(flag_wins.status, 0) << flag_wins.err;
  EXPECT_EQ(run_rtvk({"devices"}, {"RTVK_DEVICE=no-such-gpu"}).status, 2);

  // A loader that offers an NVIDIA GPU instead (the test layer's disguise of lavapipe).
  const auto disguise = test::fault_environment("disguise-device");
  const auto nvidia = run_rtvk({"devices", "--device", "nvidia"}, disguise);
  EXPECT_EQ(nvidia.status, 0) << nvidia.err;
  EXPECT_NE(nvidia.out.find("* 0: rtvk disguised GPU [discrete]"), std::string::npos) << nvidia.out;
  EXPECT_NE(nvidia.out.find("driver NVIDIA, 555.42.02"), std::string::npos) << nvidia.out;
  EXPECT_EQ(run_rtvk({"devices", "--device", "lavapipe"}, disguise).status, 2);
}

// A Vulkan 1.0 device (the test layer aborts the process if it is asked what only Vulkan 1.1
// devices answer): listed as unusable, and a render on it refused, never a crash.
TEST_F(CliGpu, AVulkan10DeviceIsListedAsUnusableWithoutA11Query) {
  const auto old = test::fault_environment("vulkan-1.0");
  const auto listed = run_rtvk({"devices"}, old);
  // Listed; then no device to render on (1), or the one the suite selects refused (2).
  EXPECT_TRUE(listed.status == 1 || listed.status == 2) << listed.status << " " << listed.err;
  EXPECT_NE(listed.out.find("unusable: supports only Vulkan 1.0.0"), std::string::npos)
      << listed.out;
  EXPECT_EQ(listed.err.find("test layer"), std::string::npos) << listed.err;
  test::temp_dir dir;
  const auto out = (dir.path() / "x.png").string();
  const auto r = run_rtvk({"render", "--backend", "gpu", "-o", out}, old);
  EXPECT_TRUE(r.status == 1 || r.status == 2) << r.status << " " << r.err;
  EXPECT_NE(r.err.find("supports only Vulkan 1.0.0"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliGpu, DeviceSelectorsThatMatchNothingAreUsageErrors) {
  test::temp_dir dir;
  const auto out = dir.path() / "x.png";
  for (const char* sel : {"99", "no-such-gpu"}) {
    const auto r = run_rtvk({"render", "--backend", "gpu", "--device", sel, "-o", out.string()});
    EXPECT_EQ(r.status, 2) << sel << ": " << r.err;
    EXPECT_NE(r.err.find(std::string("--device: '") + sel), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("0: "), std::string::npos) << "lists the devices: " << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  // By name, case-insensitively.
  if (test::test_device().empty()) {
    const auto r =
        run_rtvk({"render", "--backend", "gpu", "--device", "LLVMPIPE", "-o", out.string()});
    EXPECT_EQ(r.status, 0) << r.err;
  }
}

TEST(CliNoDevice, GpuBackendExplainsHowToGetADevice) {
  test::temp_dir dir;
  const auto out = dir.path() / "x.png";
  const std::vector<std::string> no_driver{"VK_DRIVER_FILES=/nonexistent/icd.json",
                                           "VK_ICD_FILENAMES=/nonexistent/icd.json"};
  const auto gpu = run_rtvk({"render", "--backend", "gpu", "-o", out.string()}, no_driver);
  EXPECT_EQ(gpu.status, 1) << gpu.err;
  EXPECT_NE(gpu.err.find("mesa-vulkan-drivers"), std::string::npos) << gpu.err;
  EXPECT_NE(gpu.err.find("--backend cpu"), std::string::npos) << gpu.err;
  EXPECT_FALSE(fs::exists(out));

  const auto fallback = run_rtvk({"render", "--backend", "auto", "-o", out.string()}, no_driver);
  EXPECT_EQ(fallback.status, 0) << fallback.err;
  EXPECT_NE(fallback.err.find("rendering on the CPU"), std::string::npos) << fallback.err;
  EXPECT_TRUE(fs::exists(out));
}

TEST(CliCompare, TroubleAndSizeMismatch) {
  test::temp_dir dir;
  const auto a = (dir.path() / "a.ppm").string(), b = (dir.path() / "b.ppm").string();
  ASSERT_EQ(run_rtvk({"render", "-q", "--width", "40", "-o", a}).status, 0);
  ASSERT_EQ(run_rtvk({"render", "-q", "--width", "41", "-o", b}).status, 0);
  EXPECT_EQ(run_rtvk({"compare", a, b}).status, 1);  // different sizes
  EXPECT_EQ(run_rtvk({"compare", a, a}).status, 0);
  EXPECT_EQ(run_rtvk({"compare", a, (dir.path() / "missing.ppm").string()}).status, 2);
  const auto truncated = (dir.path() / "t.ppm").string();
  std::ofstream(truncated) << "P6\n40 22\n255\nabc";
  const auto t = run_rtvk({"compare", a, truncated});
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.err.find("truncated"), std::string::npos) << t.err;
  const auto fake_png = (dir.path() / "f.png").string();
  std::ofstream(fake_png) << "not a png";
  EXPECT_EQ(run_rtvk({"compare", a, fake_png}).status, 2);
  EXPECT_EQ(run_rtvk({"compare", a, a, "--tolerance", "300"}).status, 2);
}

TEST_F(CliGpu, BenchReportsSetUpTimeToFirstSampleAndDeviceTime) {
  test::temp_dir dir;
  const auto json = (dir.path() / "bench.json").string();
  const auto r = run_rtvk(
      gpu_args({"bench", "--scene", "seed", "--width", "32", "--repeat", "2", "--json", json}));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("set-up"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("first sample after"), std::string::npos) << r.out;
  const nlohmann::json records = nlohmann::json::parse(test::slurp(json));
  int gpu_records = 0;
  for (const auto& rec : records) {
    if (rec["backend"] == "cpu") {  // set up with every render: no separate figures
      EXPECT_TRUE(rec["setup_seconds"].is_null()) << rec.dump();
      EXPECT_TRUE(rec["first_sample_seconds"].is_null()) << rec.dump();
      EXPECT_TRUE(rec["gpu_seconds"].is_null()) << rec.dump();
      continue;
    }
    ++gpu_records;
    const double setup = rec["setup_seconds"], first = rec["first_sample_seconds"];
    EXPECT_GT(setup, 0) << rec.dump();
    EXPECT_GT(first, setup) << "the first sample comes after the set-up: " << rec.dump();
    EXPECT_EQ(rec["rays"], 576) << "one ray per pixel of 32 x 18: " << rec.dump();
    // lavapipe's compute queue has timestamps: the device time is measured, within the render's.
    const double device = rec["gpu_seconds"], whole = rec["seconds"];
    EXPECT_GT(device, 0) << rec.dump();
    EXPECT_LE(device, whole) << rec.dump();
  }
  EXPECT_EQ(gpu_records, 2);
}

// Timings under the validation layer are slower: a validated bench says so in its records.
TEST_F(CliGpu, BenchTakesTheGpuFlagsAndSaysWhenValidationIsOn) {
  test::temp_dir dir;
  for (const bool validate : {false, true}) {
    const auto json = (dir.path() / "bench.json").string();
    std::vector<std::string> args{"bench", "--scene", "seed", "--width",       "32", "--backend",
                                  "gpu",   "--json",  json,   "--gpu-timeout", "60"};
    if (validate) args.push_back("--validate");
    const auto r = run_rtvk(gpu_args(args), {"RTVK_VALIDATE="});
    ASSERT_EQ(r.status, 0) << r.err;
    const nlohmann::json records = nlohmann::json::parse(test::slurp(json));
    ASSERT_EQ(records.size(), 1u) << records.dump();
    const std::string device = records[0]["device"];
    EXPECT_EQ(device.find(", validation layer on") != std::string::npos, validate) << device;
  }
  EXPECT_EQ(run_rtvk({"bench", "--gpu-timeout", "0"}).status, 2) << "checked as for render";
}

// A validated run that the layer found problems in fails, writing nothing: the layer's
// best-practices checks (VK_LAYER_ENABLES) report rtvk's small allocations as warnings, which
// stand in for real findings here.
TEST_F(CliGpu, ValidationFindingsFailRenderAndBench) {
  test::temp_dir dir;
  const auto out = (dir.path() / "out.png").string();
  const std::vector<std::string> picky{
      "VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT"};
  const auto r = run_rtvk(
      gpu_args({"render", "--scene", "seed", "--backend", "gpu", "--validate", "-o", out}), picky);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("the Vulkan validation layer reported "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("problem(s) (above); no image written"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  const auto b = run_rtvk(
      gpu_args({"bench", "--scene", "seed", "--width", "32", "--backend", "gpu", "--validate"}),
      picky);
  EXPECT_EQ(b.status, 1) << b.err;
  EXPECT_NE(b.err.find("the Vulkan validation layer reported "), std::string::npos) << b.err;
}

}  // namespace
}  // namespace rtvk
