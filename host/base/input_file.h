#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

namespace rtvk {

// A file given as input, open for reading, that is known to be a regular file: a folder, a
// device, a FIFO or a socket would block or never end. The type is checked before opening (so no
// device is opened at all) and again on the open descriptor (so a path swapped in between is
// caught); a FIFO is opened non-blocking, so it cannot hold rtvk while it waits for a writer.
// Throws usage_error naming `what` (e.g. "scene file") and the path.
class regular_file {
 public:
  regular_file(const std::filesystem::path& path, const std::string& what);
  ~regular_file();
  regular_file(const regular_file&) = delete;
  regular_file& operator=(const regular_file&) = delete;

  int fd() const { return fd_; }
  std::uint64_t size() const { return size_; }  // when opened
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;  // as given, for messages
  int fd_ = -1;                 // open for reading
  std::uint64_t size_ = 0;      // bytes, from fstat
};

// The whole content of a regular file of at most `max_bytes` bytes. Reading stops after
// max_bytes + 1, so neither a special file nor one that grows while read can make it run
// forever. Throws usage_error naming `what` and the path.
std::string read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                              const std::string& what);

}  // namespace rtvk
