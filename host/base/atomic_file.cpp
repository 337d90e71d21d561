#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

namespace rtvk {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& call, const fs::path& path, int err) {
  throw std::runtime_error(call + "(" + path.string() + "): " + std::strerror(err));
}

fs::path folder_of(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// A name beside the target that no other file has, for the moment before a rename.
fs::path temp_name(const fs::path& target) {
  static thread_local std::mt19937_64 random(std::random_device{}());
  char suffix[17];
  std::snprintf(suffix, sizeof suffix, "%016llx", static_cast<unsigned long long>(random()));
  return folder_of(target) / ("." + target.filename().string() + ".tmp-" + suffix);
}

void write_all(int fd, std::string_view bytes, const fs::path& path) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail("write", path, errno);
    bytes.remove_prefix(std::size_t(n));
  }
}

// The test suite's way to land a SIGKILL between writing and committing: with
// RTVK_TEST_PAUSE_BEFORE_COMMIT=S set, every write says so on stderr and waits S seconds there.
void test_pause_before_commit(const fs::path& path) {
  const char* seconds = std::getenv("RTVK_TEST_PAUSE_BEFORE_COMMIT");
  if (!seconds || !*seconds) return;
  std::fprintf(stderr, "rtvk: test pause: %s written, not yet committed\n", path.c_str());
  std::fflush(stderr);
  std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(seconds)));
}

// The errors open(O_TMPFILE) gives where the kernel or the file system does not offer it.
bool lacks_o_tmpfile(int err) {
  return err == EOPNOTSUPP || err == EISDIR || err == EINVAL;
}

// The folder's entry for the new file reaches the disk too, not only the file's data.
void sync_folder(const fs::path& target) {
  const int fd = ::open(folder_of(target).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail("open", folder_of(target), errno);
  const int rc = ::fsync(fd), err = errno;
  ::close(fd);
  if (rc != 0 && err != EINVAL) fail("fsync", folder_of(target), err);  // EINVAL: cannot sync
}

// An open file descriptor, closed on destruction.
struct descriptor {
  int fd = -1;
  ~descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

// O_TMPFILE: the data is written to a file with no name at all, and the complete file gets its
// name in one step, so a process killed at any moment leaves nothing behind. Returns false,
// having written nothing, where the file system or kernel does not offer it.
bool write_unnamed(const fs::path& target, std::string_view bytes) {
  descriptor file;
  file.fd = ::open(folder_of(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (file.fd < 0) {
    if (lacks_o_tmpfile(errno)) return false;
    fail("open(O_TMPFILE)", folder_of(target), errno);
  }
  write_all(file.fd, bytes, target);
  if (::fsync(file.fd) != 0) fail("fsync", target, errno);
  test_pause_before_commit(target);
  const std::string self = "/proc/self/fd/" + std::to_string(file.fd);
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, target.c_str(), AT_SYMLINK_FOLLOW) == 0) {
    sync_folder(target);
    return true;
  }
  if (errno == ENOENT && !fs::exists("/proc/self/fd")) return false;  // no /proc mounted
  if (errno != EEXIST) fail("linkat", target, errno);
  // linkat never replaces a file: name the complete file beside it, then rename it over.
  fs::path temp = temp_name(target);
  while (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) != 0) {
    if (errno != EEXIST) fail("linkat", temp, errno);
    temp = temp_name(target);
  }
  if (::rename(temp.c_str(), target.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    fail("rename", target, err);
  }
  sync_folder(target);
  return true;
}

// Where O_TMPFILE is missing: a named temporary file, removed on any failure, renamed into place.
void write_named(const fs::path& target, std::string_view bytes) {
  std::string temp = (folder_of(target) / ("." + target.filename().string() + ".tmp-XXXXXX"));
  descriptor file;
  file.fd = ::mkstemp(temp.data());
  if (file.fd < 0) fail("mkstemp", temp, errno);
  try {
    // mkstemp creates the file 0600; give it the mode a plain open() would have.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    if (::fchmod(file.fd, 0666 & ~mask) != 0) fail("fchmod", temp, errno);
    write_all(file.fd, bytes, temp);
    if (::fsync(file.fd) != 0) fail("fsync", temp, errno);
    test_pause_before_commit(target);
    if (::rename(temp.c_str(), target.c_str()) != 0) fail("rename", target, errno);
  } catch (...) {
    ::unlink(temp.c_str());
    throw;
  }
  sync_folder(target);
}

}  // namespace

int try_create_in(const fs::path& folder) {
  int fd = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0 && lacks_o_tmpfile(errno)) {
    std::string probe = (folder / ".rtvk-write-test-XXXXXX").string();
    fd = ::mkstemp(probe.data());
    if (fd >= 0) ::unlink(probe.c_str());
  }
  if (fd < 0) return errno;
  ::close(fd);
  return 0;
}

void write_file_atomically(const fs::path& path, std::string_view bytes) {
  // RTVK_TEST_NO_O_TMPFILE: the tests' way to reach the fallback on a system that has O_TMPFILE.
  if (std::getenv("RTVK_TEST_NO_O_TMPFILE") == nullptr && write_unnamed(path, bytes)) return;
  write_named(path, bytes);
}

}  // namespace rtvk
