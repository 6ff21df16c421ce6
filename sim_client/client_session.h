// A sim_client command's connection to the service on top of ServiceConnection: keeps
// messages that arrive while it waits for something else, confirms that the service has
// taken earlier messages (a StatsRequest round trip), sets the view (falling back from
// the shared-memory sink when the service cannot give it), and waits for the frame of a
// given pose.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "protocol/messages.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::sim {

using Clock = std::chrono::steady_clock;

// True when the FrameReady pose echo `echo` is the pose `sent` (exact: the protocol carries
// doubles unchanged). Compares time, position and attitude.
bool same_pose(const protocol::Pose& echo, const protocol::Pose& sent);

// "InvalidField: Pose.alt_m -600 out of range [-500, 100000]"
std::string describe_error(const protocol::Error& e);

class ClientSession {
 public:
  // address: tcp://HOST:PORT or unix:PATH. Throws client::ConnectionError (one line).
  ClientSession(const std::string& address, const std::string& client_name);

  const protocol::Welcome& welcome() const { return connection_->welcome(); }
  bool offers(std::uint32_t capability) const { return (welcome().capabilities & capability) != 0; }

  std::uint64_t send(const protocol::Message& m) { return connection_->send(m); }

  // The next message (kept ones first), or nullopt at the deadline. Throws ConnectionError
  // when the service closes the connection.
  std::optional<protocol::Message> next(Clock::time_point deadline);

  // Waits until the service has handled every message sent so far: a StatsRequest and its
  // Stats answer when the service offers Stats (its network thread answers in order, after
  // rejecting any earlier message with an Error), else a quiet period of `quiet`. Returns
  // the Errors that arrived meanwhile; other messages are kept for next(). Throws
  // ConnectionError on timeout.
  std::vector<protocol::Error> sync(std::chrono::milliseconds timeout,
                                    std::chrono::milliseconds quiet = std::chrono::milliseconds(300));

  // Sends the view and confirms it. When the service rejects it with SinkUnavailable and
  // the view asked for shared memory besides another sink, sends it again without shared
  // memory (note on `warn`). Returns the view in effect; throws RunError (usage_errors.h)
  // when the service rejects it.
  protocol::SetView set_view(protocol::SetView view, const std::function<void(const std::string&)>& warn);

  // Waits for the FrameReady echoing `pose` (sent with sequence number pose_seq). Returns
  // nullopt when the service answers the pose with an Error or reports RenderFailed (the
  // error goes to `on_error`) and throws RunError after `timeout`. FrameReady of other
  // poses and unrelated Errors go to on_other_frame / on_error.
  std::optional<protocol::FrameReady> wait_frame(const protocol::Pose& pose, std::uint64_t pose_seq,
                                                 std::chrono::milliseconds timeout,
                                                 const std::function<void(const protocol::Error&)>& on_error,
                                                 const std::function<void(const protocol::FrameReady&)>& on_other_frame = {});

 private:
  std::unique_ptr<client::ServiceConnection> connection_;
  std::deque<protocol::Message> kept_;
};

}  // namespace cloudsvc::sim
