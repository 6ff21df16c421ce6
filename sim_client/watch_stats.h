// Counters of `sim_client watch`: frames seen in the shared-memory ring, gaps in their
// numbers, frame rate per report interval, and the age of the newest frame.
#pragma once

#include <cstdint>
#include <string>

#include "protocol/shm_layout.h"

namespace cloudsvc::sim {

class WatchStats {
 public:
  // initial_latest: the ring's newest frame number when watching starts (frames already
  // there are not counted).
  explicit WatchStats(std::uint64_t initial_latest) : last_(initial_latest) {}

  // The ring's newest frame number at time t_s (seconds since watching started). A higher
  // number than before is one frame received; numbers jumped over are skipped (the watcher
  // polled too slowly, or frames went to other sinks only). A lower number means the
  // service restarted: counting continues from it.
  void observe(std::uint64_t latest, double t_s);
  // Starts a new report interval at t_s.
  void start_interval(double t_s);

  std::uint64_t newest() const { return last_; }
  std::uint64_t received() const { return received_; }
  std::uint64_t skipped() const { return skipped_; }

  // "t 3.0 s: 12 frames (+4), 4.0 frames/s, newest #57 64x36 RGBA16F linear, skipped 0, age 0.21 s"
  // info: the newest frame's slot header (size and format), or null when none was read.
  // The rate counts frames since start_interval; age is the time since the newest frame was
  // first seen ("-" before any).
  std::string report_line(double t_s, const cloudsvc_shm_slot* info) const;
  // "watch: 12 frames in 3.0 s (4.0 frames/s), newest #57, skipped 0"
  std::string summary_line(double t_s) const;

 private:
  std::uint64_t last_ = 0;
  std::uint64_t received_ = 0, skipped_ = 0;
  std::uint64_t interval_received_ = 0;
  double interval_start_s_ = 0.0;
  double newest_seen_s_ = -1.0;  // when last_ was first seen, s; < 0 before any frame
};

// "RGBA16F linear", "RGBA8 sRGB" or "format N".
std::string shm_format_name(std::uint32_t pixel_format);

}  // namespace cloudsvc::sim
