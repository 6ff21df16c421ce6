// The numbers a replay or a sweep reports at the end: frames, poses, wall time, throughput
// and the latency and render-time distributions from FrameReady.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cloudsvc::sim {

struct Distribution {
  std::size_t count = 0;
  double mean = 0.0, median = 0.0, p95 = 0.0, max = 0.0;  // in the unit of the values
};
// median and p95 by nearest rank: the ceil(0.5 n)-th and ceil(0.95 n)-th smallest value.
// All zero for no values.
Distribution summarize(std::vector<double> values);

struct ReplaySummary {
  std::size_t frames = 0;         // FrameReady received for our poses
  std::size_t poses_sent = 0;
  std::size_t poses_refused = 0;  // answered with an Error (or RenderFailed)
  double wall_s = 0.0;            // from the first pose sent to the last frame, s
  std::vector<double> latency_ms; // FrameReady.latency_ms, ms
  std::vector<double> render_ms;  // FrameReady.render_ms, ms
  bool realtime = false;
};

// One line, e.g.
// "replay: 5 frames, 5 poses sent, 3.21 s, 1.56 frames/s, latency mean 612.3 ms p95 700.1 ms
//  max 702.0 ms, render mean 580.2 ms"
// followed, with --realtime, by "; 63 poses superseded before rendering (latest wins)" and,
// when some were refused, "; 2 poses refused by the service".
std::string format_replay_summary(const ReplaySummary& s);

struct SweepSummary {
  std::size_t rows = 0;              // entries rendered (manifest rows)
  std::size_t entries = 0;           // entries in the sweep file
  std::size_t refused = 0;           // poses the service refused
  std::size_t nonfinite_frames = 0;  // frames with NaN/Inf pixels
  double wall_s = 0.0;               // from the first message sent to the last row, s
  std::vector<double> latency_ms;    // FrameReady.latency_ms of the rendered entries, ms
  std::string manifest;              // path of manifest.csv
};

// One line, e.g.
// "sweep: 3 of 3 entries rendered in 1.50 s, 2.00 frames/s, latency median 40.0 ms p95
//  55.0 ms, manifest /x/manifest.csv"
// followed, when some were, by "; 1 refused by the service" and "; 2 frames with NaN/Inf
// pixels". frames/s = rows / wall_s (including the EXR read-back per frame).
std::string format_sweep_summary(const SweepSummary& s);

}  // namespace cloudsvc::sim
