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
  return "not a regular file";
}

// An open descriptor of a regular file, closed on destruction.
class regular_file {
 public:
  regular_file(const std::filesystem::path& path, const std::string& what) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0)
      throw usage_error(path.string() + ": cannot open " + what + " (" + std::strerror(errno) +
                        ")");
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
      const char* kind = kind_of(st.st_mode);
      ::close(fd_);
      throw usage_error(path.string() + ": is " + std::string(kind) + ", not a regular " + what);
    }
    size_ = std::uint64_t(st.st_size);
    ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  }
  ~regular_file() { ::close(fd_); }
  regular_file(const regular_file&) = delete;
  regular_file& operator=(const regular_file&) = delete;

  int fd() const { return fd_; }
  std::uint64_t size() const { return size_; }  // when opened

 private:
  int fd_ = -1;             // open for reading
  std::uint64_t size_ = 0;  // bytes, from fstat
};

[[noreturn]] void too_large(const std::filesystem::path& path, std::uint64_t max_bytes,
                            const std::string& what) {
  throw usage_error(path.string() + ": " + what + " is larger than the " +
                    format_number(double(max_bytes) / double(1 << 20)) + " MiB rtvk reads");
}

}  // namespace

void check_regular_file(const std::filesystem::path& path, const std::string& what) {
  const regular_file file(path, what);
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
