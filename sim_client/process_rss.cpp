// /proc/PID/status VmRSS (process_rss.h).
#include "sim_client/process_rss.h"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>
#include <string>

namespace cloudsvc::sim {

std::optional<std::uint64_t> vmrss_bytes_of_status(std::string_view text) {
  constexpr std::string_view kKey = "VmRSS:";
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t eol = std::min(text.find('\n', at), text.size());
    std::string_view line = text.substr(at, eol - at);
    at = eol + 1;
    if (line.substr(0, kKey.size()) != kKey) continue;
    line.remove_prefix(kKey.size());
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    std::uint64_t kb = 0;
    const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), kb);
    if (ec != std::errc() || std::string_view(end, line.data() + line.size()) != " kB") return std::nullopt;
    return kb * 1024;  // the kernel's "kB" are KiB
  }
  return std::nullopt;
}

std::optional<std::uint64_t> process_rss_bytes(int pid) {
  if (pid <= 0) return std::nullopt;
  std::ifstream f("/proc/" + std::to_string(pid) + "/status");
  if (!f) return std::nullopt;
  std::stringstream s;
  s << f.rdbuf();
  return vmrss_bytes_of_status(s.str());
}

void RssRange::add(std::uint64_t bytes) {
  if (samples == 0) start = max = bytes;
  max = std::max(max, bytes);
  end = bytes;
  ++samples;
}

}  // namespace cloudsvc::sim
