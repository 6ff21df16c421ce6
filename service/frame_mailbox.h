// Hand-off from the network thread (decoded, validated client messages) to the render
// thread (DESIGN.md §1). Poses are latest-wins: a newer pose replaces an unrendered one
// (counted as dropped), so a fast sender never builds a backlog. Everything else that
// changes state (view, weather, tiles, time) is kept in arrival order: nothing accepted
// is lost. The render thread takes everything pending at once.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <variant>
#include <vector>

#include "protocol/messages.h"

namespace cloudsvc {

using SteadyTime = std::chrono::steady_clock::time_point;

struct PendingPose {
  protocol::Pose pose;
  SteadyTime received;
  std::uint64_t client_id = 0;
};

struct PendingRender {
  std::uint64_t request_id = 0;
  std::uint64_t client_id = 0;
  SteadyTime received;
};

// A state change, applied by the render thread in arrival order.
using StateChange = std::variant<protocol::SetView, protocol::WeatherLayers, protocol::WeatherMapTile,
                                 protocol::SetTime>;

struct MailboxBatch {
  std::optional<PendingPose> pose;        // newest pose since the last batch
  std::vector<StateChange> changes;       // in arrival order
  std::vector<PendingRender> renders;     // one-shot render requests
  bool stop = false;
};

class FrameMailbox {
 public:
  void post_pose(PendingPose p);
  void post_change(StateChange c);
  void post_render(PendingRender r);
  void request_stop();

  // Blocks until something is pending or `timeout` passes; returns (and clears) it.
  MailboxBatch take(std::chrono::milliseconds timeout);

  std::uint64_t poses_received() const;
  std::uint64_t poses_dropped() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  MailboxBatch pending_;
  std::uint64_t poses_received_ = 0;
  std::uint64_t poses_dropped_ = 0;
};

}  // namespace cloudsvc
