#include "job_flags.h"

namespace rtvk {

void add_job_options(CLI::App& cmd, job_request& jobs) {
  cmd.add_option("-o,--output", jobs.output,
                 "Output image: .png, .ppm, or .exr (linear float with the sample range, for "
                 "rtvk merge); {camera}, {frame} and {frame:04} are filled in")
      ->required();
  cmd.add_option("--camera", jobs.cameras,
                 "Camera of the scene to render (repeatable), or all; default: the first")
      ->type_name("NAME|all");
  cmd.add_option("--frames", jobs.frames,
                 "Animation frames A:B (A up to, not including, B) or one frame N; default 0")
      ->type_name("A:B|N");
  cmd.add_option("--fps", jobs.fps, "Frames per second: frame f shows time f / fps")
      ->capture_default_str();
  cmd.add_option("--region", jobs.region,
                 "Render only this rectangle of the image: x,y,w,h in pixels from the top left")
      ->type_name("X,Y,W,H");
  cmd.add_option("--samples", jobs.samples,
                 "Render only samples A:B of each pixel's --spp (for splitting a render)")
      ->type_name("A:B");
}

}  // namespace rtvk
