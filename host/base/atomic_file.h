#pragma once
#include <filesystem>
#include <string_view>

namespace rtvk {

// Writes bytes so that `path` holds either its old content or the complete new one, never a
// truncated file, and no partial file is ever left beside it, even by SIGKILL: the data goes to
// an unnamed O_TMPFILE in the target's folder, is flushed to disk, and only then gets a name
// (linked in, or, over an existing file, linked beside it and renamed over it); then the folder
// is flushed. Where O_TMPFILE or /proc is missing, a named temporary file beside `path` (removed
// on failure) is renamed into place instead. Throws std::runtime_error naming the failing call
// and errno's text.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

// Whether write_file_atomically can create a file in `folder`, tried the same way (an unnamed
// O_TMPFILE, so a probe killed midway leaves nothing; a named file, removed at once, only where
// that is missing). Returns 0, or the errno of the failure.
int try_create_in(const std::filesystem::path& folder);

}  // namespace rtvk
