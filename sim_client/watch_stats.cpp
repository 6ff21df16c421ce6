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
  (void)t_s;
}

void WatchStats::Latency::add(double ms) {
  ++count;
  sum_ms += ms;
  if (count == 1 || ms > max_ms) max_ms = ms;
}

std::string WatchStats::Latency::text() const {
  if (count == 0) return "latency -";
  char buf[96];
  std::snprintf(buf, sizeof buf, "latency mean %.1f ms max %.1f ms", sum_ms / static_cast<double>(count), max_ms);
  return buf;
}

void WatchStats::record_latency(double ms) {
  interval_latency_.add(ms);
  total_latency_.add(ms);
}

void WatchStats::start_interval(double t_s) {
  interval_start_s_ = t_s;
  interval_received_ = 0;
  interval_latency_ = {};
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
  std::snprintf(buf, sizeof buf, ", skipped %llu, ", static_cast<unsigned long long>(skipped_));
  return out + buf + interval_latency_.text();
}

std::string WatchStats::summary_line(double t_s) const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "watch: %llu frames in %.1f s (%.1f frames/s), newest #%llu, skipped %llu",
                static_cast<unsigned long long>(received_), t_s, t_s > 0.0 ? static_cast<double>(received_) / t_s : 0.0,
                static_cast<unsigned long long>(last_), static_cast<unsigned long long>(skipped_));
  std::string out = buf;
  if (total_latency_.count > 0) out += ", " + total_latency_.text();
  return out;
}

}  // namespace cloudsvc::sim
