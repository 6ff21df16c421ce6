// Replay summary (run_summary.h).
#include "sim_client/run_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace cloudsvc::sim {

Distribution summarize(std::vector<double> values) {
  Distribution d;
  d.count = values.size();
  if (values.empty()) return d;
  std::sort(values.begin(), values.end());
  d.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  auto nearest_rank = [&](double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
    return values[std::max<std::size_t>(rank, 1) - 1];
  };
  d.median = nearest_rank(0.5);
  d.p95 = nearest_rank(0.95);
  d.max = values.back();
  return d;
}

std::string format_replay_summary(const ReplaySummary& s) {
  const Distribution latency = summarize(s.latency_ms);
  const Distribution render = summarize(s.render_ms);
  const double rate = s.wall_s > 0.0 ? static_cast<double>(s.frames) / s.wall_s : 0.0;  // frames/s
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "replay: %zu frames, %zu poses sent, %.2f s, %.2f frames/s, latency mean %.1f ms p95 %.1f ms "
                "max %.1f ms, render mean %.1f ms",
                s.frames, s.poses_sent, s.wall_s, rate, latency.mean, latency.p95, latency.max, render.mean);
  std::string out = buf;
  const std::size_t unrendered = s.poses_sent - std::min(s.poses_sent, s.frames + s.poses_refused);
  if (s.realtime) out += "; " + std::to_string(unrendered) + " poses superseded before rendering (latest wins)";
  if (s.poses_refused > 0) out += "; " + std::to_string(s.poses_refused) + " poses refused by the service";
  return out;
}

std::string format_sweep_summary(const SweepSummary& s) {
  const Distribution latency = summarize(s.latency_ms);
  const double rate = s.wall_s > 0.0 ? static_cast<double>(s.rows) / s.wall_s : 0.0;  // frames/s
  char buf[256];
  std::snprintf(buf, sizeof buf, "sweep: %zu of %zu entries rendered in %.2f s, %.2f frames/s, latency median %.1f ms p95 %.1f ms, manifest ",
                s.rows, s.entries, s.wall_s, rate, latency.median, latency.p95);
  std::string out = buf + s.manifest;
  if (s.refused) out += "; " + std::to_string(s.refused) + " refused by the service";
  if (s.nonfinite_frames) out += "; " + std::to_string(s.nonfinite_frames) + " frames with NaN/Inf pixels";
  return out;
}

}  // namespace cloudsvc::sim
