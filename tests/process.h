#pragma once
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "software_device.h"
#include "temp_dir.h"

extern char** environ;

namespace rtvk::test {

struct process_result {
  int status = -1;       // exit status, or 128 + signal number
  std::string out;       // everything written to stdout
  std::string err;       // everything written to stderr
  long max_rss_kib = 0;  // the child's peak resident memory
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The environment of a child the tests start: the current one, with RTVK_DEVICE naming the device
// under test (software_device.h), then `overrides` ("NAME=value") replacing or adding variables;
// an override of a bare "NAME" removes that variable. A later override of a name wins.
inline std::vector<std::string> environment_with(const std::vector<std::string>& overrides) {
  std::vector<std::string> all{device_environment()};
  all.insert(all.end(), overrides.begin(), overrides.end());
  const auto name_of = [](const std::string& o) { return o.substr(0, o.find('=')) + '='; };
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) {
    const std::string entry(*e);
    bool replaced = false;
    for (const auto& o : all) replaced |= entry.compare(0, name_of(o).size(), name_of(o)) == 0;
    if (!replaced) env.push_back(entry);
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    bool overridden_later = false;
    for (std::size_t j = i + 1; j < all.size(); ++j)
      overridden_later |= name_of(all[j]) == name_of(all[i]);
    if (!overridden_later && all[i].find('=') != std::string::npos) env.push_back(all[i]);
  }
  return env;
}

// The rtvk executable (or `program`) started with args (stdin from /dev/null, stdout to a
// file, stderr to a file or to `stderr_path` when given, e.g. a pseudo-terminal), not yet waited
// for: tests can signal it while it runs.
class running_rtvk {
 public:
  running_rtvk(const std::vector<std::string>& args,
               const std::vector<std::string>& env_overrides = {},
               const std::string& stderr_path = "", const std::string& program = RTVK_EXE) {
    out_ = (io_.path() / "out").string();
    err_ = stderr_path.empty() ? (io_.path() / "err").string() : stderr_path;
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (stderr_path.empty())
      posix_spawn_file_actions_addopen(&fa, 2, err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    else
      posix_spawn_file_actions_addopen(&fa, 2, err_.c_str(), O_RDWR | O_NOCTTY, 0);
    std::vector<std::string> storage{program};
    storage.insert(storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& s : storage) argv.push_back(s.data());
    argv.push_back(nullptr);
    std::vector<std::string> env = environment_with(env_overrides);
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    const int rc = posix_spawn(&pid_, program.c_str(), &fa, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) throw std::runtime_error("posix_spawn failed");
    captured_stderr_ = stderr_path.empty();
  }
  ~running_rtvk() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  running_rtvk(const running_rtvk&) = delete;
  running_rtvk& operator=(const running_rtvk&) = delete;

  void signal(int sig) const { ::kill(pid_, sig); }

  // What the child has written to stderr so far (when it goes to a file).
  std::string stderr_so_far() const { return slurp(err_); }

  // Waits (up to `limit`) until the child has installed a handler for `sig`, read from the
  // SigCgt mask in /proc/<pid>/status: a signal sent earlier would find the default action.
  bool wait_until_catching(int sig, std::chrono::milliseconds limit) const {
    const auto end = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < end) {
      std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
      std::string line;
      while (std::getline(status, line)) {
        if (line.rfind("SigCgt:", 0) != 0) continue;
        const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
        if (mask & (1ull << (sig - 1))) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

  // Waits up to `limit`; a child still running then is killed (status 128 + SIGKILL), so a hang
  // fails the test instead of stalling the suite.
  process_result wait_at_most(std::chrono::milliseconds limit) {
    const auto end = std::chrono::steady_clock::now() + limit;
    int wstatus = 0;
    struct rusage usage {};
    pid_t rc;
    while ((rc = wait4(pid_, &wstatus, WNOHANG, &usage)) == 0 || (rc < 0 && errno == EINTR)) {
      if (std::chrono::steady_clock::now() > end) ::kill(pid_, SIGKILL);
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return reaped(wstatus, usage);
  }

  process_result wait() {
    int wstatus = 0;
    struct rusage usage {};
    while (wait4(pid_, &wstatus, 0, &usage) < 0) {
    }
    return reaped(wstatus, usage);
  }

 private:
  process_result reaped(int wstatus, const struct rusage& usage) {
    pid_ = -1;
    process_result r;
    r.max_rss_kib = usage.ru_maxrss;
    r.status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    r.out = slurp(out_);
    if (captured_stderr_) r.err = slurp(err_);
    return r;
  }

  temp_dir io_;                  // holds the output files
  std::string out_;              // stdout's file
  std::string err_;              // stderr's file or terminal
  bool captured_stderr_ = true;  // stderr went to a file this class reads back
  pid_t pid_ = -1;               // the child, until waited for
};

// Runs the rtvk executable with args, stdin from /dev/null, and waits for it.
inline process_result run_rtvk(const std::vector<std::string>& args,
                               const std::vector<std::string>& env_overrides = {}) {
  return running_rtvk(args, env_overrides).wait();
}

// The same, killed after `limit`: for inputs that once made rtvk hang.
inline process_result run_rtvk_within(std::chrono::milliseconds limit,
                                      const std::vector<std::string>& args,
                                      const std::vector<std::string>& env_overrides = {}) {
  return running_rtvk(args, env_overrides).wait_at_most(limit);
}

}  // namespace rtvk::test
