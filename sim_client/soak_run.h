// A `sim_client soak` run: N client connections on one asio::io_context whose thread pool
// is sized from std::thread::hardware_concurrency(), each sending poses along its own
// circle at a fixed rate for a duration, while the service's resident memory is sampled
// once a second (/proc/PID/status). Returns everything measured (soak_summary.h).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim_client/soak_summary.h"

namespace cloudsvc::sim {

struct SoakOptions {
  std::vector<std::string> addresses;  // clients are spread over them round-robin
  std::size_t clients = 4;
  double rate_hz = 60.0;               // poses per second per client
  double duration_s = 60.0;            // of pose sending
  std::uint32_t width = 640, height = 360;  // SetView size
  std::uint64_t render_every = 0;      // a RenderRequest after every K-th pose of a client; 0 = none
  int service_pid = 0;                 // > 0: sample its VmRSS
  std::size_t threads = 0;             // io threads; 0 = std::thread::hardware_concurrency() (at least 1)
};

// Runs the soak:
//  1. connects every client (5 s each for connect + Hello/Welcome; all at once);
//  2. client 0 sets the view when the service offers a sink for it (SetView: size, the
//     shared-memory sink if offered) and takes a StatsRequest round trip; without a sink
//     to ask for (a service without --shm) no SetView is sent and the service renders its
//     own view (its --size); then client 0 sends one warm-up pose and waits for a frame
//     (at most 10 minutes): the service's first frame compiles shaders and builds weather
//     volumes, which is not what the run measures;
//  3. every client flies for duration_s from a common start, then sends a StatsRequest
//     and closes when it and every RenderRequest of the client are answered (at most 30 s
//     of draining; later ones are closed and counted as drain timeouts);
//  4. the service's Stats before and after, VmRSS before, once a second and after.
// progress(line) gets a line every 10 s of flying ("soak: 10 s, 80008 poses, 784 frames
// received, rss 243.3 MiB"); may be empty. Throws client::ConnectionError when a client cannot
// connect, RunError when the service refuses the view.
SoakSummary run_soak(const SoakOptions& o, const std::function<void(const std::string&)>& progress = {});

}  // namespace cloudsvc::sim
