// Resident set size of another process on the same machine, from /proc/PID/status
// (Linux): for watching a service's memory during a soak run.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace cloudsvc::sim {

// VmRSS of process pid, bytes (the kernel reports kB = 1024 bytes); nullopt when the
// process does not exist (any more) or its status has no VmRSS line (a zombie, a kernel
// thread) or cannot be read.
std::optional<std::uint64_t> process_rss_bytes(int pid);

// The VmRSS line of a /proc/PID/status text, bytes; nullopt when there is none.
std::optional<std::uint64_t> vmrss_bytes_of_status(std::string_view status_text);

// Start, largest and last of a series of RSS samples, bytes.
struct RssRange {
  std::uint64_t start = 0, max = 0, end = 0;
  std::size_t samples = 0;  // 0: no sample (no --service-pid, or the process was gone)
  void add(std::uint64_t bytes);
};

}  // namespace cloudsvc::sim
