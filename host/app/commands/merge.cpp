#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "image_io.h"
#include "merge.h"
#include "partial_image.h"
#include "quantize.h"
#include "render_memory.h"

namespace rtvk {
namespace {

struct merge_options {
  std::vector<std::string> parts;     // .exr pieces from rtvk render
  std::string output;                 // .png, .ppm, or .exr to merge further later
  std::string ppm_format = "P3";      // P3 or P6
  bool quiet = false;                 // no summary line
  bool allow_mixed_versions = false;  // merge pieces of different rtvk versions
};

int run_merge(const merge_options& o) {
  check_output_path(o.output, "--output", true);
  render_merger merger(o.allow_mixed_versions);
  for (std::size_t k = 0; k < o.parts.size(); ++k) {
    const partial_image piece = read_partial_exr(o.parts[k]);  // one piece in memory at a time
    if (k == 0) {
      check_output_size(o.output, piece.image_width, piece.image_height, "--output");
      check_render_memory(piece.image_width, piece.image_height, 3);
    }
    merger.add(o.parts[k], piece);
  }
  const merged_render m = merger.finish();
  if (format_for_path(o.output, "--output") == file_format::exr) {
    write_partial_exr(make_partial(m.fb, m.summary), o.output);
  } else {
    write_image(quantize(m.fb, m.summary.encoding()), o.output,
                o.ppm_format == "P6" ? ppm_encoding::binary_p6 : ppm_encoding::ascii_p3);
  }
  if (!o.quiet)
    std::fprintf(stderr,
                 "rtvk: merged %zu part(s) of %s [camera %s, frame %d]: %dx%d, samples "
                 "%d:%d -> %s\n",
                 o.parts.size(), m.summary.scene.c_str(), m.summary.camera.c_str(), m.summary.frame,
                 m.fb.width(), m.fb.height(), m.summary.window.sample_begin,
                 m.summary.window.sample_end, o.output.c_str());
  return 0;
}

}  // namespace

command_action add_merge_command(CLI::App& app) {
  auto o = std::make_shared<merge_options>();
  CLI::App* cmd = app.add_subcommand(
      "merge", "Combine .exr pieces of one render (tiles, sample ranges) into the whole image");
  cmd->add_option("PARTS", o->parts, ".exr files written by rtvk render")->required();
  cmd->add_option("-o,--output", o->output, "Merged image: .png, .ppm, or .exr")->required();
  cmd->add_option("--ppm-format", o->ppm_format, "PPM flavour: P3 (ASCII) or P6 (binary)")
      ->transform(CLI::IsMember({"P3", "P6"}, CLI::ignore_case))
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", o->quiet, "No summary line");
  cmd->add_flag("--allow-mixed-versions", o->allow_mixed_versions,
                "Merge pieces rendered by different rtvk versions or shaders (refused otherwise)");
  return [o] { return run_merge(*o); };
}

}  // namespace rtvk
