// `sim_client watch --shm NAME`: follows the service's shared-memory frame ring and prints,
// once a second, how many frames arrived, the frame rate, the newest frame, gaps and the
// delivery latency (watcher's clock minus the slot's publish time).
#include <CLI/CLI.hpp>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <ctime>
#include <cstdio>
#include <memory>
#include <thread>

#include "common/option_values.h"
#include "protocol/shm/shm_frame_reader.h"
#include "protocol/shm/shm_name.h"
#include "sim_client/commands.h"
#include "sim_client/usage_errors.h"
#include "sim_client/watch_stats.h"

namespace cloudsvc::sim {

namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kName = "watch";
constexpr std::chrono::milliseconds kPollInterval{1};  // latest_frame() is one atomic load
constexpr std::chrono::seconds kReportInterval{1};

std::atomic<bool> g_interrupted{false};

// CLOCK_REALTIME, ns since 1970 (the clock of cloudsvc_shm_slot.publish_unix_ns).
std::int64_t realtime_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}
extern "C" void on_interrupt(int) { g_interrupted = true; }

struct WatchArgs {
  std::string shm, seconds;
};

struct WatchOptions {
  std::string shm;
  double seconds = 0.0;  // 0 = until interrupted
};

WatchOptions validate(const WatchArgs& a) {
  WatchOptions o;
  if (a.shm.empty()) cli::fail("--shm", a.shm, "required: the ring name given to cloudsvc serve --shm");
  if (a.shm.find('/') != std::string::npos) cli::fail("--shm", a.shm, "give the name without '/'");
  if (!valid_shm_name(a.shm)) cli::fail("--shm", a.shm, "expected " + shm_name_rule() + ", as given to cloudsvc serve --shm");
  o.shm = a.shm;
  if (!a.seconds.empty()) o.seconds = cli::parse_number("--seconds", a.seconds, cli::Range{0.0, 31536000.0, true, "seconds"});
  return o;
}

int run_watch(const WatchOptions& o) {
  std::unique_ptr<ShmFrameReader> reader;
  try {
    reader = std::make_unique<ShmFrameReader>(o.shm);
  } catch (const std::exception& e) {
    throw RunError("--shm " + o.shm + ": " + e.what());
  }
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  const auto start = Clock::now();
  WatchStats stats(reader->latest_frame());
  auto next_report = start + kReportInterval;
  cloudsvc_shm_slot newest{};  // header of the newest frame read
  std::uint64_t described = 0;  // its frame number, 0 before any
  for (;;) {
    const auto now = Clock::now();
    const double t = std::chrono::duration<double>(now - start).count();
    const bool done = g_interrupted || (o.seconds > 0.0 && t >= o.seconds);
    const std::uint64_t latest = reader->latest_frame();
    if (latest != stats.newest()) {
      // A new frame: its slot header (no pixels) for size, format and publish time.
      const std::uint64_t after = latest > described ? described : 0;  // a restarted service counts from 1
      bool got = false;
      try {
        got = reader->read_latest_header(after, newest);
      } catch (const std::exception& e) {  // a corrupt ring (ShmFrameReader checks every size)
        throw RunError("--shm " + o.shm + ": " + e.what());
      }
      if (got) {
        described = newest.frame_number;
        stats.record_latency(static_cast<double>(realtime_ns() - newest.publish_unix_ns) / 1e6);
      }
    }
    stats.observe(latest, t);
    if (now >= next_report || done) {
      std::printf("%s\n", stats.report_line(t, described ? &newest : nullptr).c_str());
      std::fflush(stdout);
      stats.start_interval(t);
      next_report += kReportInterval;
    }
    if (done) break;
    std::this_thread::sleep_for(kPollInterval);
  }
  std::printf("%s\n", stats.summary_line(std::chrono::duration<double>(Clock::now() - start).count()).c_str());
  std::fflush(stdout);
  return cli::kExitOk;
}

}  // namespace

Command add_watch_command(CLI::App& app) {
  auto args = std::make_shared<WatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Follow the service's shared-memory frame ring: once a second print frames received, frame rate, newest "
             "frame number, size and format, frames skipped and the latency from the service publishing a frame "
             "to the watcher reading it");
  cmd->add_option("--shm", args->shm, "Name of the ring, as given to cloudsvc serve --shm (without '/'); required")
      ->type_name("NAME");
  cmd->add_option("--seconds", args->seconds, "Stop after this many seconds, (0, 31536000]; default: until Ctrl-C")
      ->type_name("S");
  cmd->footer(std::string(kExitCodesHelp) + "\nExample: sim_client watch --shm cloudsvc-frames --seconds 10");
  return {cmd, [args]() -> int { return run_watch(validate(*args)); }};
}

}  // namespace cloudsvc::sim
