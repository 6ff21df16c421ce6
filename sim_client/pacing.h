// Wall-clock deadlines of paced sends (replay --realtime, cigi --fps, soak): a time offset in
// seconds (double) turned into a steady_clock time point without overflow. The clock counts
// int64 nanoseconds, 292 years; an offset is at most a flight log's span (years 1900-2199,
// sim_client/value_checks.h) and is held to 200 years (6.3e9 s) before the conversion, which
// no run lasts. NaN and negative offsets are due at once.
#pragma once

#include <algorithm>
#include <chrono>

namespace cloudsvc::sim {

inline constexpr double kMaxPacingOffset_s = 200.0 * 365.25 * 86400.0;

inline std::chrono::steady_clock::time_point due_after(std::chrono::steady_clock::time_point start, double offset_s) {
  const double s = offset_s > 0.0 ? std::min(offset_s, kMaxPacingOffset_s) : 0.0;  // NaN: 0
  return start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}

}  // namespace cloudsvc::sim
