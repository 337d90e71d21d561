#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "image_compare.h"
#include "image_io.h"

namespace rtvk {
namespace {

struct compare_options {
  std::string a, b;  // the two images
  std::string diff;  // heat-map output, or empty
  agreement rule;    // when they count as alike
};

int run_compare(const compare_options& o) {
  if (!o.diff.empty()) check_output_path(o.diff, "--diff");
  const image_rgb8 a = read_image(o.a);
  const image_rgb8 b = read_image(o.b);
  if (!o.diff.empty()) check_output_size(o.diff, a.width, a.height, "--diff");
  if (a.width != b.width || a.height != b.height) {
    std::printf("different sizes: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const image_difference d = compare_images(a, b, o.rule.tolerance);
  const bool alike = agrees(d, o.rule);
  std::printf("size      %dx%d\n", d.width, d.height);
  std::printf("max abs   %d levels (of 255)\n", d.max_abs);
  std::printf("mean abs  %.5f levels\n", d.mean_abs);
  if (std::isinf(d.psnr_db))
    std::printf("PSNR      inf dB (identical)\n");
  else
    std::printf("PSNR      %.2f dB\n", d.psnr_db);
  std::printf("over tol  %lld pixels (%.4f%%) differ by more than %d levels\n",
              static_cast<long long>(d.pixels_over), 100 * d.share_over, o.rule.tolerance);
  std::printf("verdict   %s (at most %.4f%% of pixels may exceed the tolerance",
              alike ? "alike" : "different", 100 * o.rule.max_share);
  if (o.rule.min_psnr_db > 0) std::printf("; PSNR at least %.1f dB", o.rule.min_psnr_db);
  std::printf(")\n");
  if (!o.diff.empty()) write_image(difference_heatmap(a, b), o.diff);
  return alike ? 0 : 1;
}

}  // namespace

command_action add_compare_command(CLI::App& app) {
  auto opts = std::make_shared<compare_options>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare two images (PNG, PPM P3/P6); exit 0 alike, 1 different, 2 trouble");
  cmd->add_option("A", opts->a, "First image")->required();
  cmd->add_option("B", opts->b, "Second image")->required();
  cmd->add_option("--diff", opts->diff, "Write a heat map of the differences (.png or .ppm)");
  cmd->add_option("--tolerance", opts->rule.tolerance,
                  "Largest channel difference, in 8-bit levels, that still counts as equal")
      ->check(CLI::Range(0, 255))
      ->capture_default_str();
  cmd->add_option("--max-share", opts->rule.max_share,
                  "Largest fraction of pixels (0 to 1) allowed beyond the tolerance")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--min-psnr", opts->rule.min_psnr_db,
                  "Smallest PSNR, in dB, that still counts as alike (0: not checked)")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  return [opts] { return run_compare(*opts); };
}

}  // namespace rtvk
