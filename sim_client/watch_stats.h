// Counters of `sim_client watch`: frames seen in the shared-memory ring, gaps in their
// numbers, frame rate per report interval, and the delivery latency of the frames (the
// watcher's clock when it first read a frame minus the frame's publish time in the ring).
#pragma once

#include <cstdint>
#include <string>

#include "protocol/shm/shm_layout.h"

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
  // Latency of a newly seen frame, ms: CLOCK_REALTIME when the watcher read its slot header
  // minus the slot's publish_unix_ns.
  void record_latency(double ms);
  // Starts a new report interval at t_s.
  void start_interval(double t_s);

  std::uint64_t newest() const { return last_; }
  std::uint64_t received() const { return received_; }
  std::uint64_t skipped() const { return skipped_; }

  // "t 3.0 s: 12 frames (+4), 4.0 frames/s, newest #57 64x36 RGBA16F linear, skipped 0,
  //  latency mean 0.6 ms max 1.1 ms"
  // info: the newest frame's slot header (size and format), or null when none was read.
  // The rate and the latency count the frames since start_interval ("latency -" when no
  // latency was recorded in it).
  std::string report_line(double t_s, const cloudsvc_shm_slot* info) const;
  // "watch: 12 frames in 3.0 s (4.0 frames/s), newest #57, skipped 0, latency mean 0.6 ms max 1.1 ms"
  // (the latency part only when some was recorded).
  std::string summary_line(double t_s) const;

 private:
  std::uint64_t last_ = 0;
  std::uint64_t received_ = 0, skipped_ = 0;
  std::uint64_t interval_received_ = 0;
  double interval_start_s_ = 0.0;
  struct Latency {
    std::uint64_t count = 0;
    double sum_ms = 0.0, max_ms = 0.0;
    void add(double ms);
    std::string text() const;  // "latency mean 0.6 ms max 1.1 ms" or "latency -"
  };
  Latency interval_latency_, total_latency_;
};

// "RGBA16F linear", "RGBA8 sRGB" or "format N".
std::string shm_format_name(std::uint32_t pixel_format);

}  // namespace cloudsvc::sim
