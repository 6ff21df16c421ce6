// Counters of `sim_client watch` (watch_stats.h).
#include "sim_client/watch_stats.h"

#include <cstdio>

namespace cloudsvc::sim {

void WatchStats::observe(std::uint64_t latest, double t_s) {
  if (latest == last_) return;
  if (latest > last_) {
    skipped_ += latest - last_ - 1;
  }
  // latest < last_: a restarted service numbers from 1 again; take it as a new baseline frame.
  ++received_;
  ++interval_received_;
  last_ = latest;
  newest_seen_s_ = t_s;
}

void WatchStats::start_interval(double t_s) {
  interval_start_s_ = t_s;
  interval_received_ = 0;
}

std::string shm_format_name(std::uint32_t f) {
  if (f == CLOUDSVC_SHM_RGBA16F_LINEAR) return "RGBA16F linear";
  if (f == CLOUDSVC_SHM_RGBA8_SRGB) return "RGBA8 sRGB";
  return "format " + std::to_string(f);
}

std::string WatchStats::report_line(double t_s, const cloudsvc_shm_slot* info) const {
  const double span = t_s - interval_start_s_;
  const double fps = span > 0.0 ? static_cast<double>(interval_received_) / span : 0.0;
  char buf[256];
  std::snprintf(buf, sizeof buf, "t %.1f s: %llu frames (+%llu), %.1f frames/s, newest #%llu", t_s,
                static_cast<unsigned long long>(received_), static_cast<unsigned long long>(interval_received_), fps,
                static_cast<unsigned long long>(last_));
  std::string out = buf;
  if (info) {
    std::snprintf(buf, sizeof buf, " %ux%u %s", info->width, info->height, shm_format_name(info->pixel_format).c_str());
    out += buf;
  }
  std::snprintf(buf, sizeof buf, ", skipped %llu, age ", static_cast<unsigned long long>(skipped_));
  out += buf;
  if (newest_seen_s_ < 0.0) {
    out += "-";
  } else {
    std::snprintf(buf, sizeof buf, "%.2f s", t_s - newest_seen_s_);
    out += buf;
  }
  return out;
}

std::string WatchStats::summary_line(double t_s) const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "watch: %llu frames in %.1f s (%.1f frames/s), newest #%llu, skipped %llu",
                static_cast<unsigned long long>(received_), t_s, t_s > 0.0 ? static_cast<double>(received_) / t_s : 0.0,
                static_cast<unsigned long long>(last_), static_cast<unsigned long long>(skipped_));
  return buf;
}

}  // namespace cloudsvc::sim
