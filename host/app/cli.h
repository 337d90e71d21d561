#pragma once

namespace rtvk {

// The whole command line: parses, runs the subcommand, and maps every outcome to an exit status
// (0 success, 1 failure while running, 2 bad usage or bad input). Never throws.
int run_cli(int argc, char** argv);

}  // namespace rtvk
