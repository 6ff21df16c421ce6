// The soak run: connect, set the view, fly, drain, collect (soak_run.h).
#include "sim_client/soak_run.h"

#include <asio.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "sim_client/client_session.h"
#include "sim_client/process_rss.h"
#include "sim_client/service_connection.h"
#include "sim_client/soak_client.h"
#include "sim_client/soak_track.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kConnectTimeout = std::chrono::milliseconds(5000);  // per client: connect + Hello/Welcome
constexpr auto kSyncTimeout = std::chrono::seconds(10);            // the view's StatsRequest round trip
constexpr auto kDrainTimeout = std::chrono::seconds(30);           // after the last pose: the final Stats
// The first frame of a fresh service compiles shaders and builds weather volumes: about
// 5-20 s on llvmpipe with 2 busy cores; 10 minutes means the service is stuck.
constexpr auto kWarmUpTimeout = std::chrono::minutes(10);
constexpr auto kStartDelay = std::chrono::milliseconds(100);       // arms every client's timer before the first pose
constexpr auto kRssInterval = std::chrono::seconds(1);
constexpr auto kProgressInterval = std::chrono::seconds(10);
constexpr double kViewFov_deg = 60.0;  // horizontal field of view of the SetView, as sim_client's default

// The io_context's threads, stopped and joined however run_soak leaves.
class IoThreads {
 public:
  IoThreads(asio::io_context& io, std::size_t n) : io_(io), work_(asio::make_work_guard(io)) {
    for (std::size_t i = 0; i < n; ++i) threads_.emplace_back([this] { io_.run(); });
  }
  ~IoThreads() { stop(); }
  void stop() {
    work_.reset();
    io_.stop();
    for (std::thread& t : threads_)
      if (t.joinable()) t.join();
  }

 private:
  asio::io_context& io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_;
  std::vector<std::thread> threads_;
};

// VmRSS of the service once a second on the io_context (a timer, not a thread of its own).
class RssSampler : public std::enable_shared_from_this<RssSampler> {
 public:
  RssSampler(asio::io_context& io, int pid) : timer_(asio::make_strand(io)), pid_(pid) {}
  void start() {
    sample();
    arm();
  }
  void stop() {
    asio::post(timer_.get_executor(), [self = shared_from_this()] {
      self->stopped_ = true;
      self->timer_.cancel();
    });
  }
  void sample() {
    const std::optional<std::uint64_t> rss = process_rss_bytes(pid_);
    std::lock_guard lock(mutex_);
    if (rss) range_.add(*rss);
    else gone_ = true;
  }
  RssRange range() const {
    std::lock_guard lock(mutex_);
    return range_;
  }
  bool gone() const {
    std::lock_guard lock(mutex_);
    return gone_;
  }

 private:
  void arm() {
    timer_.expires_after(kRssInterval);
    timer_.async_wait([self = shared_from_this()](const asio::error_code& ec) {
      if (ec || self->stopped_) return;
      self->sample();
      self->arm();
    });
  }
  asio::steady_timer timer_;
  int pid_;
  bool stopped_ = false;  // on the timer's strand
  mutable std::mutex mutex_;
  RssRange range_;
  bool gone_ = false;
};

// Client 0's sync (SoakClient::sync) with a deadline; closes every client and throws
// ConnectionError when the service does not answer or the connection ends.
SoakSyncResult sync(const std::vector<std::shared_ptr<SoakClient>>& clients, std::vector<protocol::Message> messages) {
  std::future<SoakSyncResult> synced = clients.front()->sync(std::move(messages));
  const bool answered = synced.wait_for(kSyncTimeout) == std::future_status::ready;
  SoakSyncResult r = answered ? synced.get() : SoakSyncResult{};
  if (!r.stats) {
    for (auto& c : clients) c->close();
    throw client::ConnectionError(answered ? "the connection ended while waiting for the service's Stats"
                                           : "timed out waiting for the service to answer a StatsRequest");
  }
  return r;
}

std::string mib_text(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return buf;
}

}  // namespace

SoakSummary run_soak(const SoakOptions& o, const std::function<void(const std::string&)>& progress) {
  if (o.addresses.empty() || o.clients == 0 || !(o.rate_hz > 0.0) || !(o.duration_s > 0.0))
    throw std::invalid_argument("run_soak: needs an address, a client, a positive rate and a positive duration");
  SoakSummary s;
  s.addresses = o.addresses;
  s.rate_hz = o.rate_hz;
  s.duration_s = o.duration_s;
  s.width = o.width;
  s.height = o.height;
  s.render_every = o.render_every;
  s.service_pid = o.service_pid;
  // The clients only format, write and parse small messages: a thread per core is plenty
  // and leaves the scheduling to the OS (the service may share the machine).
  s.threads = o.threads > 0 ? o.threads : std::max<std::size_t>(1, std::thread::hardware_concurrency());

  asio::io_context io;
  IoThreads threads(io, s.threads);
  std::shared_ptr<RssSampler> rss;
  if (o.service_pid > 0) {
    rss = std::make_shared<RssSampler>(io, o.service_pid);
    rss->start();
  }

  std::vector<std::shared_ptr<SoakClient>> clients;
  for (std::size_t i = 0; i < o.clients; ++i) {
    SoakClientPlan plan;
    plan.index = i;
    plan.rate_hz = o.rate_hz;
    plan.render_every = o.render_every;
    clients.push_back(std::make_shared<SoakClient>(io, o.addresses[i % o.addresses.size()], plan));
  }
  std::vector<std::future<std::string>> connected;
  for (auto& c : clients) connected.push_back(c->connect(kConnectTimeout));
  std::string problem;
  for (std::size_t i = 0; i < clients.size(); ++i) {
    const std::string p = connected[i].get();
    if (!p.empty() && problem.empty()) problem = "client " + std::to_string(i) + ": " + p;
  }
  if (!problem.empty()) {
    for (auto& c : clients) c->close();
    throw client::ConnectionError(problem);
  }

  // The view: the scene is the service's, shared by all clients, so one client sets it.
  std::vector<protocol::Message> view_messages;
  if (clients.front()->welcome().capabilities & protocol::capability::kSinkShm) {
    protocol::SetView view;
    view.width = o.width;
    view.height = o.height;
    view.hfov_deg = kViewFov_deg;
    view.sinks = protocol::sink::kShm;
    view_messages.push_back(view);
    s.view_sent = true;
  }
  const SoakSyncResult viewed = sync(clients, std::move(view_messages));
  if (!viewed.errors.empty()) {
    for (auto& c : clients) c->close();
    throw RunError("the service rejected the view: " + describe_error(viewed.errors.front()));
  }

  // One frame before the clock starts (soak_client.h, warm_up): the pose client 0 flies
  // first, a second before its track starts, so that it is not one of the run's poses.
  SoakTrack track;
  protocol::Pose warm = track.pose(0, -1.0);
  warm.flags = protocol::pose_flag::kTeleport;
  const Clock::time_point warm_start = Clock::now();
  std::future<std::optional<double>> warmed = clients.front()->warm_up(warm);
  if (warmed.wait_for(kWarmUpTimeout) != std::future_status::ready) {
    for (auto& c : clients) c->close();
    throw client::ConnectionError("no frame for the warm-up pose within 10 minutes");
  }
  const std::optional<double> warm_ms = warmed.get();
  if (!warm_ms) {
    for (auto& c : clients) c->close();
    throw client::ConnectionError("the connection ended while waiting for the warm-up frame");
  }
  s.warm_up_s = std::chrono::duration<double>(Clock::now() - warm_start).count();
  s.service_start = sync(clients, {}).stats;  // the counters the run's deltas start from

  const Clock::time_point start = Clock::now() + kStartDelay;
  const Clock::time_point end =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.duration_s));
  std::vector<std::future<void>> flown;
  for (auto& c : clients) flown.push_back(c->fly(start, end));
  const Clock::time_point deadline = end + kDrainTimeout;
  Clock::time_point next_progress = start + kProgressInterval;
  Clock::time_point all_stopped = end;
  for (std::size_t i = 0; i < flown.size();) {
    const Clock::time_point wake = std::min(next_progress, deadline);
    if (flown[i].wait_until(wake) == std::future_status::ready) {
      ++i;
      continue;
    }
    if (Clock::now() >= deadline) break;
    if (progress) {
      std::uint64_t poses = 0, frames = 0;
      for (const auto& c : clients) {
        poses += c->poses_sent_live();
        frames += c->frames_live();
      }
      std::string line = "soak: " + std::to_string(static_cast<long long>(
                                        std::chrono::duration<double>(Clock::now() - start).count())) +
                         " s, " + std::to_string(poses) + " poses, " + std::to_string(frames) + " frames received";
      if (rss && rss->range().samples) line += ", rss " + mib_text(rss->range().end);
      progress(line);
    }
    next_progress += kProgressInterval;
  }
  all_stopped = std::min(all_stopped, Clock::now());
  for (auto& c : clients) c->close();  // no-op for the clients that finished
  for (auto& f : flown) f.wait();
  s.run_s = std::max(0.0, std::chrono::duration<double>(all_stopped - start).count());

  if (rss) {
    rss->stop();
    rss->sample();  // after the run
    s.rss = rss->range();
    s.service_gone = rss->gone();
  }
  threads.stop();
  for (const auto& c : clients) {
    s.clients.push_back(c->stats());
    // the latest of the clients' final Stats: most poses, then most frames (both clients
    // ask at the same moment, so the pose counts often tie while a frame completes between
    // the two answers)
    const auto& end_stats = c->final_service_stats();
    const auto later = [](const protocol::Stats& a, const protocol::Stats& b) {
      return std::pair(a.poses_received, a.frames_rendered) > std::pair(b.poses_received, b.frames_rendered);
    };
    if (end_stats && (!s.service_end || later(*end_stats, *s.service_end))) s.service_end = end_stats;
  }
  return s;
}

}  // namespace cloudsvc::sim
