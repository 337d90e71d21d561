#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "image_compare.h"
#include "image_io.h"
#include "partial_image.h"
#include "quantize.h"

namespace rtvk {
namespace {

struct compare_options {
  std::string a, b;  // the two images
  std::string diff;  // heat-map output, or empty
  agreement rule;    // when they count as alike
};

bool is_exr(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".exr") == 0;
}

// An rtvk .exr (a render's linear means) as the 8-bit image its PNG would be.
image_rgb8 encoded(const partial_image& p) {
  framebuffer fb(p.window.width, p.window.height);
  for (int y = 0; y < p.window.height; ++y)
    for (int x = 0; x < p.window.width; ++x) {
      const float* c = &p.rgb[(std::size_t(y) * std::size_t(p.window.width) + std::size_t(x)) * 3];
      fb.at(x, y) = color(c[0], c[1], c[2]);
    }
  return quantize(fb, p.encoding());
}

// Two renders' linear colors: the mean squared error over pixels and channels (the noise of a
// render against a converged reference), and the reference's mean square, for a relative figure.
void print_linear_error(const partial_image& a, const partial_image& b) {
  double squared = 0, reference = 0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) {
    const double d = double(a.rgb[k]) - double(b.rgb[k]);
    squared += d * d;
    reference += double(b.rgb[k]) * double(b.rgb[k]);
  }
  const double n = double(a.rgb.size());
  std::printf("mse       %.6e (linear, mean over pixels and channels)\n", squared / n);
  std::printf("rel mse   %.6e (mse / mean square of B)\n",
              reference > 0 ? squared / reference : 0.0);
}

int run_compare(const compare_options& o) {
  if (!o.diff.empty()) check_output_path(o.diff, "--diff");
  // Two .exr renders: their linear colors too (read as rtvk wrote them).
  const bool linear = is_exr(o.a) && is_exr(o.b);
  std::optional<partial_image> pa, pb;
  if (linear) {
    pa = read_partial_exr(o.a);
    pb = read_partial_exr(o.b);
  }
  const image_rgb8 a = linear ? encoded(*pa) : read_image(o.a);
  const image_rgb8 b = linear ? encoded(*pb) : read_image(o.b);
  if (!o.diff.empty()) check_output_size(o.diff, a.width, a.height, "--diff");
  if (a.width != b.width || a.height != b.height) {
    std::printf("different sizes: %dx%d vs %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const image_difference d = compare_images(a, b, o.rule.tolerance);
  const bool alike = agrees(d, o.rule);
  std::printf("size      %dx%d\n", d.width, d.height);
  if (linear) print_linear_error(*pa, *pb);
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
      "compare",
      "Compare two images (PNG, PPM P3/P6, or two rtvk .exr renders: then also their linear mean "
      "squared error); exit 0 alike, 1 different, 2 trouble");
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
