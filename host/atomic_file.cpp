#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rtvk {
namespace {

[[noreturn]] void fail(const std::string& call, const std::filesystem::path& path, int err) {
  throw std::runtime_error(call + "(" + path.string() + "): " + std::strerror(err));
}

// Owns the temporary file until it is renamed into place; removes it on any failure.
class temp_file {
 public:
  explicit temp_file(const std::filesystem::path& target) {
    const auto dir = target.has_parent_path() ? target.parent_path() : ".";
    path_ = (dir / ("." + target.filename().string() + ".tmp-XXXXXX")).string();
    fd_ = ::mkstemp(path_.data());
    if (fd_ < 0) fail("mkstemp", path_, errno);
  }
  ~temp_file() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(path_.c_str());
  }
  temp_file(const temp_file&) = delete;
  temp_file& operator=(const temp_file&) = delete;

  void write_all(std::string_view bytes) {
    while (!bytes.empty()) {
      const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) fail("write", path_, errno);
      bytes.remove_prefix(std::size_t(n));
    }
  }

  void commit(const std::filesystem::path& target) {
    // mkstemp creates the file 0600; give it the mode a plain open() would have.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(fd_, 0666 & ~mask) != 0) fail("fchmod", path_, errno);
    if (::fsync(fd_) != 0) fail("fsync", path_, errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("close", path_, errno);
    if (::rename(path_.c_str(), target.c_str()) != 0) fail("rename", target, errno);
    committed_ = true;
  }

 private:
  std::string path_;        // the temporary file, in the target's folder
  int fd_ = -1;             // open descriptor, -1 once closed
  bool committed_ = false;  // renamed into place: nothing to clean up
};

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  temp_file tmp(path);
  tmp.write_all(bytes);
  tmp.commit(path);
}

}  // namespace rtvk
