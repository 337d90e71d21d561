#pragma once
#include <filesystem>
#include <string_view>

namespace rtvk {

// Writes bytes to a temporary file beside `path`, flushes it to disk and renames it into place,
// so `path` holds either its old content or the complete new one, never a truncated file.
// Throws std::runtime_error naming the failing call and errno's text.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace rtvk
