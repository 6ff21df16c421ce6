// One connection of `sim_client soak`: connects and shakes hands as ServiceConnection does
// (Hello with every capability, Welcome, same major), then, driven by a timer on an
// asio::io_context shared by all clients, sends its poses at a fixed rate, reads every
// reply and counts it (soak_summary.h). All of a client's handlers run on its own strand,
// so its state needs no lock; the run talks to it through futures.
#pragma once

#include <asio.hpp>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "protocol/framing.h"
#include "protocol/messages.h"
#include "sim_client/soak_summary.h"
#include "sim_client/soak_track.h"

namespace cloudsvc::sim {

struct SoakClientPlan {
  std::size_t index = 0;          // which client: its place on the track
  double rate_hz = 60.0;          // poses per second
  std::uint64_t render_every = 0; // a RenderRequest after every K-th pose; 0 = none
  SoakTrack track;
};

// The answer to SoakClient::sync: the Errors answering the messages it sent, and the Stats.
struct SoakSyncResult {
  std::vector<protocol::Error> errors;
  std::optional<protocol::Stats> stats;  // nullopt: the connection ended before the answer
};

class SoakClient : public std::enable_shared_from_this<SoakClient> {
 public:
  using Clock = std::chrono::steady_clock;

  SoakClient(asio::io_context& io, std::string address, SoakClientPlan plan);

  // Connects and sends Hello. The future holds "" once the Welcome arrived, else the
  // problem in one line ("unix:/x: Connection refused", "unix:/x: refused: Busy: ...",
  // "unix:/x: no Welcome within 5 s").
  std::future<std::string> connect(std::chrono::milliseconds timeout);
  // The service's Welcome; valid once connect() reported success.
  const protocol::Welcome& welcome() const { return welcome_; }

  // Sends `messages`, then a StatsRequest. The future is ready when the Stats arrives (the
  // service answers in order: an Error about any of `messages` comes before it) or the
  // connection ends. Only before fly().
  std::future<SoakSyncResult> sync(std::vector<protocol::Message> messages);

  // Sends `pose` and waits for the next FrameReady (normally the one echoing it; another
  // host's newer pose may supersede it): the service's first frame compiles shaders and
  // builds weather volumes (seconds on llvmpipe), which is not the steady state a soak
  // measures. Ready with the wait in ms, or nullopt when the connection ends first. Only
  // before fly(); frames before fly() are not counted.
  std::future<std::optional<double>> warm_up(const protocol::Pose& pose);

  // Sends pose k at start + k / rate_hz (the first with the teleport flag) for every k due
  // before `end` (late if the timer is late), then a StatsRequest. Ready when that is
  // answered (final_stats) and every RenderRequest sent has its FrameReady or an Error
  // answering it, or when the connection ends.
  std::future<void> fly(Clock::time_point start, Clock::time_point end);

  // Closes the connection now (the run's drain deadline passed); open futures become ready.
  void close();

  // Running totals for progress lines; any thread.
  std::uint64_t poses_sent_live() const { return poses_live_.load(std::memory_order_relaxed); }
  std::uint64_t frames_live() const { return frames_live_.load(std::memory_order_relaxed); }

  // Read only after the io_context's threads have stopped.
  const SoakClientStats& stats() const { return stats_; }
  // The Stats answering the closing StatsRequest, if it came.
  const std::optional<protocol::Stats>& final_service_stats() const { return final_stats_; }

 private:
  enum class State { Idle, Connecting, Handshake, Ready, Flying, Draining, Closed };
  struct Outstanding {
    protocol::Pose pose;
    Clock::time_point sent;
  };
  using Bytes = std::shared_ptr<std::vector<std::uint8_t>>;

  void start_connect(std::chrono::milliseconds timeout);
  void on_connected(const asio::error_code& ec, bool tcp);
  void fail_connect(const std::string& problem);
  std::uint64_t send(const protocol::Message& m);
  void write_next();
  void read();
  void on_read(const asio::error_code& ec, std::size_t n);
  void handle(protocol::Message& m);
  void on_frame(const protocol::FrameReady& f, Clock::time_point now);
  void on_stats(const protocol::Stats& s);
  void finish_if_drained();
  void tick(const asio::error_code& ec);
  void send_pose(Clock::time_point now);
  Clock::time_point due(std::uint64_t k) const;
  void lost(const std::string& reason);
  void shut();
  void finish_promises();

  asio::strand<asio::io_context::executor_type> strand_;
  asio::generic::stream_protocol::socket socket_;
  asio::steady_timer timer_;  // connect deadline, then the pose schedule
  std::string address_;
  SoakClientPlan plan_;
  State state_ = State::Idle;

  protocol::FrameDecoder decoder_;
  std::array<std::uint8_t, 65536> buffer_{};
  std::uint64_t next_seq_ = 1;
  std::deque<Bytes> queue_;     // waiting for the socket
  std::vector<Bytes> writing_;  // being written
  std::size_t queued_bytes_ = 0;  // in queue_ and writing_

  protocol::Welcome welcome_;
  std::promise<std::string> connected_;
  bool connected_done_ = false;
  std::optional<std::promise<SoakSyncResult>> sync_;
  std::set<std::uint64_t> sync_seqs_;
  SoakSyncResult sync_result_;
  std::optional<std::promise<std::optional<double>>> warm_;
  Clock::time_point warm_sent_;
  std::promise<void> flown_;
  bool flying_started_ = false, flown_done_ = false;

  Clock::time_point start_, end_;
  std::uint64_t next_pose_ = 0;
  std::uint64_t requests_made_ = 0;
  std::deque<Outstanding> outstanding_;              // own poses not yet rendered, by sim time
  struct PendingRequest {
    std::uint64_t seq = 0;  // of the RenderRequest message: an Error answering it names it
    Clock::time_point sent;
  };
  std::map<std::uint64_t, PendingRequest> requests_;  // RenderRequests not answered yet, by id
  SoakClientStats stats_;
  std::optional<protocol::Stats> final_stats_;
  std::atomic<std::uint64_t> poses_live_{0}, frames_live_{0};
};

// When pose k of a client flying from `start` to `end` at rate_hz poses per second is due:
// start + k / rate_hz, or `end` itself when that is not before `end` (such a pose is not
// sent). k / rate_hz is compared in seconds before it becomes a clock duration: at a rate
// far below one pose per run (1e-300 Hz, valid for --rate) it exceeds what the clock's
// 64-bit nanoseconds hold, and the cast had wrapped to a time long past, so every pose was
// "due" and the client sent without end.
std::chrono::steady_clock::time_point soak_pose_due(std::chrono::steady_clock::time_point start,
                                                    std::chrono::steady_clock::time_point end, std::uint64_t k,
                                                    double rate_hz);

}  // namespace cloudsvc::sim
