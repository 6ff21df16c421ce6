// What a `sim_client soak` run measured, per client and in total, and its report: one
// block of key=value lines on stdout and the same keys as JSON (--json FILE).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/messages.h"
#include "sim_client/process_rss.h"

namespace cloudsvc::sim {

// One client's counters (one connection).
struct SoakClientStats {
  std::string address;                  // where it connected
  std::uint64_t poses_sent = 0;
  std::uint64_t poses_skipped = 0;      // due but not sent: too many bytes already waiting for the socket
  std::uint64_t requests_sent = 0;      // RenderRequests (--render-every)
  std::uint64_t frames = 0;             // FrameReady received (every client gets every pose-driven frame)
  std::uint64_t own_frames = 0;         // FrameReady echoing one of this client's poses
  std::uint64_t request_frames = 0;     // FrameReady answering one of its RenderRequests
  std::vector<double> latency_ms;       // own pose sent -> its FrameReady received, ms
  std::vector<double> request_latency_ms;  // RenderRequest sent -> its FrameReady received, ms
  std::vector<double> service_latency_ms;  // FrameReady.latency_ms of own frames (the service's part), ms
  std::vector<std::uint64_t> frame_numbers;  // of the pose-driven FrameReady received
  std::map<std::string, std::uint64_t> errors;  // Error received, by code name ("Overloaded")
  bool disconnected = false;            // the connection ended before the client ended it
  std::string disconnect_reason;        // one line, when disconnected
  bool final_stats = false;             // the closing StatsRequest was answered
};

struct SoakSummary {
  // What was asked.
  std::vector<std::string> addresses;
  double rate_hz = 0.0;                  // poses per second per client
  double duration_s = 0.0;               // requested
  std::uint32_t width = 0, height = 0;   // --size
  bool view_sent = false;                // false: no sink to ask for, the service's own view was rendered
  std::uint64_t render_every = 0;        // 0 = no RenderRequests
  std::size_t threads = 0;               // io threads of the client
  // What happened.
  double warm_up_s = 0.0;                // the service's first frame before the run (soak_run.h), s
  double run_s = 0.0;                    // first pose due -> last client stopped sending, s
  std::vector<SoakClientStats> clients;
  std::optional<protocol::Stats> service_start, service_end;  // Stats before the first pose and after the last
  int service_pid = 0;                   // 0 = RSS not sampled
  RssRange rss;                          // VmRSS samples, bytes: before, once a second, after
  bool service_gone = false;             // the process vanished while sampled
};

// The report as a JSON object (keys in a fixed order; key=value lines are its flattening):
//   clients, rate_hz, duration_s, warm_up_s, run_s, connect, view, render_every, threads,
//   poses_sent, poses_skipped, requests_sent, frames_received (all clients), frames_distinct,
//   frame_rate_hz (distinct frames / run_s), own_frames,
//   latency_ms {p50, p95, max, count} (pose sent -> its FrameReady), service_latency_ms {...},
//   request_frames, request_latency_ms {...} (with --render-every),
//   errors {total, <code>: n}, disconnects, drain_timeouts,
//   service {frames_rendered, poses_received, poses_dropped} (Stats deltas over the run),
//   rss_kib {start, max, end, samples} (with --service-pid), service_gone,
//   per_client [{address, poses_sent, frames, own_frames, errors, disconnected, reason}],
//   result ("ok" or "failed: " + the soak_failures joined with "; ").
// Distributions are by nearest rank (run_summary.h), all 0 without values.
nlohmann::ordered_json soak_report(const SoakSummary& s, bool errors_expected);

// The report as lines "key=value" (nested keys joined with '.', per_client.N.key; strings
// as they are, reals with 3 decimals), after one readable first line
// "soak: 8 clients x 1000 Hz for 60 s (unix:/tmp/soak.sock), view 160x90".
std::string format_soak_report(const SoakSummary& s, bool errors_expected);

// Why the run failed, empty when it did not: a client disconnected unexpectedly, a final
// StatsRequest went unanswered, the service process vanished, no frame arrived, or (unless
// errors_expected) an Error was received. One short phrase per reason.
std::vector<std::string> soak_failures(const SoakSummary& s, bool errors_expected);

}  // namespace cloudsvc::sim
