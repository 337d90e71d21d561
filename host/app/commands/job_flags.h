#pragma once
#include <CLI/CLI.hpp>

#include "render_jobs.h"

namespace rtvk {

// The options that pick the images (cameras, frames, part of each) and name their files:
// -o, --camera, --frames, --fps, --region, --samples.
void add_job_options(CLI::App& cmd, job_request& jobs);

}  // namespace rtvk
