// service_bench: measures `cloudsvc serve` over a Unix socket on this machine:
//   1. pose-to-frame latency (client sends a pose, waits for its FrameReady), median/p95;
//   2. pose ingestion: the highest pose rate the service takes without a backlog (every
//      pose received, the newest one on screen one frame later);
//   3. frame throughput while poses stream in (frames rendered per second in step 2).
//
//   build/bin/service_bench [--size 320x180] [--frames 20]
#include <CLI/CLI.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "sim_client/service_connection.h"

namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using cloudsvc::client::ServiceConnection;
namespace protocol = cloudsvc::protocol;

struct Service {
  pid_t pid = -1;
  std::string socket;
  Service(const std::string& size) {
    socket = (std::filesystem::temp_directory_path() / ("cloudsvc_bench_" + std::to_string(::getpid()) + ".sock")).string();
    pid = ::fork();
    if (pid == 0) {
      const std::string bin = std::string(CLOUDSVC_BENCH_BIN_DIR) + "/cloudsvc";
      std::freopen("/dev/null", "w", stdout);
      ::execl(bin.c_str(), bin.c_str(), "serve", "--listen", ("unix:" + socket).c_str(), "--size", size.c_str(),
              "--weather", "broken-cumulus", "--time", "2026-06-21T14:00:00Z", static_cast<char*>(nullptr));
      _exit(127);
    }
    for (int i = 0; i < 1500 && !std::filesystem::exists(socket); ++i) std::this_thread::sleep_for(20ms);
  }
  ~Service() {
    ::kill(pid, SIGTERM);
    ::waitpid(pid, nullptr, 0);
  }
};

protocol::Pose pose(double t, double lat) {
  protocol::Pose p;
  p.sim_time_s = t;
  p.lat_deg = lat;
  p.lon_deg = 8.56;
  p.alt_m = 300.0;
  p.heading_deg = 135.0;
  p.pitch_deg = 10.0;
  return p;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Latency, pose ingestion and frame throughput of cloudsvc serve (Unix socket, this machine)"};
  std::string size = "320x180";
  int frames = 20;
  app.add_option("--size", size, "image size WxH");
  app.add_option("--frames", frames, "frames for the latency and throughput runs")->check(CLI::Range(3, 10000));
  CLI11_PARSE(app, argc, argv);

  Service svc(size);
  ServiceConnection c("unix:" + svc.socket, "service_bench", 30000ms);
  // Warm-up (shader JIT, first LUTs).
  c.send(pose(0.0, 47.45));
  c.receive_until<protocol::FrameReady>(120s);

  // 1. latency
  std::vector<double> rtt, render, service_latency;
  for (int i = 0; i < frames; ++i) {
    const auto t0 = Clock::now();
    c.send(pose(1.0 + i, 47.45 + i * 1e-5));
    const auto r = c.receive_until<protocol::FrameReady>(120s);
    rtt.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    render.push_back(r.render_ms);
    service_latency.push_back(r.latency_ms);
  }
  std::printf("# service_bench %s (llvmpipe, Unix socket)\n\n", size.c_str());
  std::printf("| measure | median | p95 |\n|---|---:|---:|\n");
  std::printf("| pose-to-frame latency, client round trip (ms) | %.1f | %.1f |\n", percentile(rtt, 0.5), percentile(rtt, 0.95));
  std::printf("| pose-to-frame latency, service's FrameReady.latency_ms | %.1f | %.1f |\n", percentile(service_latency, 0.5),
              percentile(service_latency, 0.95));
  std::printf("| render + readback (ms) | %.1f | %.1f |\n", percentile(render, 0.5), percentile(render, 0.95));

  // 2. pose ingestion: blast poses at increasing rates for 1 s each while frames render;
  // no backlog = every pose is counted as received and the last pose is rendered next.
  std::printf("\n| offered pose rate (1/s) | sent | received by service | dropped (superseded) | frames rendered | frames/s | last pose on screen after (ms) |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  double t = 1000.0;
  for (int rate : {100, 1000, 10000, 100000}) {
    c.send(protocol::StatsRequest{});
    const auto before = c.receive_until<protocol::Stats>(120s);
    const auto start = Clock::now();
    int sent = 0;
    double last_lat = 0;
    while (Clock::now() - start < 1s) {
      const auto due = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(double(sent) / rate));
      if (Clock::now() < due) std::this_thread::sleep_until(due);
      last_lat = 40.0 + (sent % 100000) * 1e-5;
      c.send(pose(t += 0.001, last_lat));
      ++sent;
      // drain notices so the service never waits on us
      while (c.receive(0ms)) {}
    }
    const auto end_send = Clock::now();
    protocol::FrameReady r{};
    while (r.pose.lat_deg != last_lat) r = c.receive_until<protocol::FrameReady>(120s);
    const double settle = std::chrono::duration<double, std::milli>(Clock::now() - end_send).count();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    c.send(protocol::StatsRequest{});
    const auto after = c.receive_until<protocol::Stats>(120s);
    const auto rendered = after.frames_rendered - before.frames_rendered;
    std::printf("| %d | %d | %llu | %llu | %llu | %.2f | %.0f |\n", rate, sent,
                static_cast<unsigned long long>(after.poses_received - before.poses_received),
                static_cast<unsigned long long>(after.poses_dropped - before.poses_dropped),
                static_cast<unsigned long long>(rendered), static_cast<double>(rendered) / elapsed, settle);
    std::fflush(stdout);
  }

  return 0;
}
