// Hand-off from the network thread (decoded, validated client messages) to the render
// thread. Poses are latest-wins: a newer pose replaces an unrendered one
// (counted as dropped), so a fast sender never builds a backlog. Everything else that
// changes state (view, weather, tiles, time) is kept in arrival order: nothing accepted
// is lost. What one client can queue is bounded, and a request over a bound is refused
// (the caller answers Overloaded) instead of being queued: at most kMaxRendersPerClient
// render requests per client, and weather tiles up to a byte budget for all clients.
// The render thread takes all state changes and the newest pose at once, but only one
// render request per client per batch, so requests of one client never hold back the
// poses (or the requests) of another for more than one frame each.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <variant>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"
#include "protocol/messages.h"

namespace cloudsvc {

using SteadyTime = std::chrono::steady_clock::time_point;

struct PendingPose {
  protocol::Pose pose;
  SteadyTime received;
  std::uint64_t client_id = 0;
  std::uint64_t seq = 0;  // the Pose's envelope seq, answered by an Error about it
};

struct PendingRender {
  std::uint64_t request_id = 0;
  std::uint64_t client_id = 0;
  SteadyTime received;
  std::uint64_t seq = 0;  // the RenderRequest's envelope seq, answered by an Error about it
};

// A state change, applied by the render thread in arrival order.
using StateChange = std::variant<protocol::SetView, protocol::WeatherLayers, protocol::WeatherMapTile,
                                 protocol::SetTime>;

struct MailboxBatch {
  std::optional<PendingPose> pose;        // newest pose since the last batch
  std::vector<StateChange> changes;       // in arrival order
  std::vector<PendingRender> renders;     // one-shot render requests
  std::vector<cigi::HostDatagram> cigi;   // CIGI host datagrams (usable or not), in arrival order
  std::uint64_t cigi_refused = 0;         // CIGI datagrams refused since the last batch (kMaxCigiDatagrams)
  bool stop = false;
};

class FrameMailbox {
 public:
  // Render requests one client may have queued or in progress.
  static constexpr std::size_t kMaxRendersPerClient = 2;

  // CIGI datagrams waiting for the render thread: a host sending faster than the render
  // thread takes them (it takes all at every batch) loses datagrams beyond this (counted).
  static constexpr std::size_t kMaxCigiDatagrams = 4096;

  explicit FrameMailbox(std::size_t tile_budget_bytes = std::size_t{256} << 20);

  void post_pose(PendingPose p);
  // False (nothing queued) when a WeatherMapTile would take the tiles received but not yet
  // applied above the budget; other changes are always queued.
  bool post_change(StateChange c);
  // False (nothing queued) when the client already has kMaxRendersPerClient requests.
  bool post_render(PendingRender r);
  // False (refused, counted) when kMaxCigiDatagrams are waiting.
  bool post_cigi(cigi::HostDatagram d);
  void request_stop();

  // The render thread reports each request it has finished (or failed) and each tile it
  // has applied (or dropped), which frees their place in the bounds.
  void render_finished(std::uint64_t client_id);
  void tile_applied(const protocol::WeatherMapTile& tile);

  // Bytes a tile holds while it waits (its texel values).
  static std::size_t tile_bytes(const protocol::WeatherMapTile& tile);

  // Blocks until something is pending or `timeout` passes; returns (and clears) it.
  MailboxBatch take(std::chrono::milliseconds timeout);

  std::uint64_t poses_received() const;
  std::uint64_t poses_dropped() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  MailboxBatch pending_;                                  // renders: all clients, arrival order
  std::map<std::uint64_t, std::size_t> renders_by_client_;  // queued + in progress
  std::size_t tile_budget_bytes_;
  std::size_t tile_bytes_ = 0;                            // received, not yet applied
  std::uint64_t poses_received_ = 0;
  std::uint64_t poses_dropped_ = 0;
};

}  // namespace cloudsvc
