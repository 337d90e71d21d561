#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

namespace rtvk {

// Checks that `path` names a regular file that can be opened for reading: a folder, a device, a
// FIFO or a socket would block or never end. Throws usage_error naming `what` (e.g. "scene
// file") and the path.
void check_regular_file(const std::filesystem::path& path, const std::string& what);

// The whole content of a regular file of at most `max_bytes` bytes. Checked on the descriptor
// it reads (no window between the check and the read), and reading stops after max_bytes + 1,
// so neither a special file nor one that grows while read can make it run forever. Throws
// usage_error naming `what` and the path.
std::string read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                              const std::string& what);

}  // namespace rtvk
