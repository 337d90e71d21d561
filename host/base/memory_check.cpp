#include "memory_check.h"

#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace rtvk {
namespace {

void consider(memory_room& room, std::uint64_t bytes, const char* limit) {
  if (room.bytes == 0 || bytes < room.bytes) room = {bytes, limit};
}

std::uint64_t mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  std::uint64_t kib = 0;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

// Bytes a cgroup's file cache holds that the kernel would drop before refusing memory: its
// inactive_file (memory.current counts the cache, which a job that reads files fills up to its
// limit).
std::uint64_t reclaimable(const std::filesystem::path& dir) {
  std::ifstream stat(dir / "memory.stat");
  std::string key;
  std::uint64_t value = 0;
  while (stat >> key >> value)
    if (key == "inactive_file") return value;
  return 0;
}

// The room under memory.max in the process's cgroup v2 folder and every one above it, up to the
// mount's root (a limit on a parent binds its children too; in a container the root is the
// container's own cgroup). "max" means no limit there.
void consider_cgroups(memory_room& room) {
  std::ifstream self("/proc/self/cgroup");
  std::string line, path;
  while (std::getline(self, line))
    if (line.rfind("0::", 0) == 0) path = line.substr(3);
  if (path.empty() || path[0] != '/') return;
  const std::filesystem::path mount("/sys/fs/cgroup");
  std::filesystem::path dir = (mount / path.substr(1)).lexically_normal();
  while (true) {
    std::ifstream max_file(dir / "memory.max"), current_file(dir / "memory.current");
    std::uint64_t max = 0, current = 0;
    if (max_file >> max && current_file >> current) {
      const std::uint64_t cache = reclaimable(dir);
      const std::uint64_t used = current > cache ? current - cache : 0;
      consider(room, max > used ? max - used : 1, "cgroup memory.max");
    }
    if (dir == mount || dir.string().size() <= mount.string().size()) break;
    dir = dir.parent_path();
  }
}

// The room under RLIMIT_AS: the limit less the address space already mapped.
void consider_address_limit(memory_room& room) {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  const std::uint64_t mapped = pages * std::uint64_t(sysconf(_SC_PAGESIZE));
  consider(room, limit.rlim_cur > mapped ? limit.rlim_cur - mapped : 1, "ulimit -v");
}

}  // namespace

memory_room available_memory() {
  memory_room room;
  if (const std::uint64_t bytes = mem_available(); bytes != 0) room = {bytes, "MemAvailable"};
  consider_cgroups(room);
  consider_address_limit(room);
  return room;
}

std::uint64_t available_memory_bytes() {
  return available_memory().bytes;
}

}  // namespace rtvk
