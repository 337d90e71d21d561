#include "input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "errors.h"
#include "format.h"

namespace rtvk {
namespace {

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "an unknown kind of file";
}

[[noreturn]] void too_large(const std::filesystem::path& path, std::uint64_t max_bytes,
                            const std::string& what) {
  throw usage_error(path.string() + ": " + what + " is larger than the " + format_bytes(max_bytes) +
                    " rtvk reads");
}

}  // namespace

regular_file::regular_file(const std::filesystem::path& path, const std::string& what)
    : path_(path) {
  auto refuse = [&](mode_t mode) {
    throw usage_error(path.string() + ": is " + std::string(kind_of(mode)) + ", not a regular " +
                      what);
  };
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) refuse(st.st_mode);
  // O_NONBLOCK: should the path become a FIFO after the stat, opening it would otherwise wait
  // for a writer forever.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0)
    throw usage_error(path.string() + ": cannot open " + what + " (" + std::strerror(errno) + ")");
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd_);
    refuse(st.st_mode);
  }
  size_ = std::uint64_t(st.st_size);
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
}

regular_file::~regular_file() {
  ::close(fd_);
}

std::string read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes,
                              const std::string& what) {
  const regular_file file(path, what);
  if (file.size() > max_bytes) too_large(path, max_bytes, what);
  std::string bytes(std::size_t(file.size()) + 1, '\0');  // one more: a file that grew shows
  std::size_t got = 0;
  while (true) {
    if (got == bytes.size()) {
      if (got > max_bytes) too_large(path, max_bytes, what);
      bytes.resize(std::min<std::size_t>(bytes.size() * 2, std::size_t(max_bytes) + 1));
    }
    const ssize_t n = ::read(file.fd(), bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw usage_error(path.string() + ": cannot read " + what + " (" + std::strerror(errno) +
                        ")");
    if (n == 0) break;
    got += std::size_t(n);
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace rtvk
