#pragma once
#include <cstdint>
#include <string>

namespace rtvk {

// Memory this process can still get, and what limits it: the least of the system's
// MemAvailable, the room under each memory.max of the process's cgroup (v2) and its ancestors
// (a Slurm job's --mem, a Kubernetes pod's limit: the node's MemAvailable is not theirs to
// use), and the room under `ulimit -v`.
struct memory_room {
  std::uint64_t bytes = 0;  // 0 when nothing could be read
  std::string limit;        // what sets it: "MemAvailable", "cgroup memory.max", "ulimit -v"
};
memory_room available_memory();

// available_memory().bytes.
std::uint64_t available_memory_bytes();

}  // namespace rtvk
