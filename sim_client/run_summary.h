// The numbers a replay reports at the end: frames, poses, wall time, throughput and the
// latency and render-time distributions from FrameReady.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace cloudsvc::sim {

struct Distribution {
  std::size_t count = 0;
  double mean = 0.0, p95 = 0.0, max = 0.0;  // in the unit of the values
};
// p95 by nearest rank: the ceil(0.95 n)-th smallest value. All zero for no values.
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

}  // namespace cloudsvc::sim
