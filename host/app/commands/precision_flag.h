#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "engine_options.h"

namespace rtvk {

// --precision: which of the CPU's two modes draws (engine_options.h's cpu_precision). `both`
// is for `rtvk bench` only (each mode timed in the same run).
void add_precision_option(CLI::App& cmd, std::string& word, bool with_both = false);

// The mode `word` names for scene argument `scene`: auto is the reference for the built-in
// scenes (the books' images, byte for byte) and fast for files (a scene file, a mesh).
cpu_precision precision_for(const std::string& word, const std::string& scene);

}  // namespace rtvk
