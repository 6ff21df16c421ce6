// Connection helpers of the sim_client commands (client_session.h).
#include "sim_client/client_session.h"

#include <algorithm>

#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {
constexpr std::chrono::milliseconds kConnectTimeout{5000};
}

bool same_pose(const protocol::Pose& echo, const protocol::Pose& sent) {
  return echo.sim_time_s == sent.sim_time_s && echo.lat_deg == sent.lat_deg && echo.lon_deg == sent.lon_deg &&
         echo.alt_m == sent.alt_m && echo.heading_deg == sent.heading_deg && echo.pitch_deg == sent.pitch_deg &&
         echo.roll_deg == sent.roll_deg;
}

std::string describe_error(const protocol::Error& e) {
  return std::string(protocol::error_code_name(e.code)) + ": " + e.text;
}

ClientSession::ClientSession(const std::string& address, const std::string& client_name)
    : connection_(std::make_unique<client::ServiceConnection>(address, client_name, kConnectTimeout)) {}

std::optional<protocol::Message> ClientSession::next(Clock::time_point deadline) {
  if (!kept_.empty()) {
    protocol::Message m = std::move(kept_.front());
    kept_.pop_front();
    return m;
  }
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return connection_->receive(std::max(left, std::chrono::milliseconds(0)));
}

std::vector<protocol::Error> ClientSession::sync(std::chrono::milliseconds timeout, std::chrono::milliseconds quiet) {
  std::vector<protocol::Error> errors;
  std::deque<protocol::Message> others;
  const bool stats = offers(protocol::capability::kStats);
  if (stats) connection_->send(protocol::StatsRequest{});
  const auto deadline = Clock::now() + (stats ? timeout : quiet);
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      if (stats) throw client::ConnectionError("timed out waiting for the service to answer a StatsRequest");
      break;
    }
    std::optional<protocol::Message> m = connection_->receive(left);
    if (!m) continue;
    if (auto* e = std::get_if<protocol::Error>(&*m)) errors.push_back(*e);
    else if (stats && std::holds_alternative<protocol::Stats>(*m)) break;
    else others.push_back(std::move(*m));
  }
  for (auto& m : others) kept_.push_back(std::move(m));
  return errors;
}

protocol::SetView ClientSession::set_view(protocol::SetView view, const std::function<void(const std::string&)>& warn) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    const std::uint64_t seq = send(view);
    std::optional<protocol::Error> rejected;
    for (const protocol::Error& e : sync(std::chrono::milliseconds(10000)))
      if (e.answers_seq == seq) rejected = e;
      else if (warn) warn("service: " + describe_error(e));
    if (!rejected) return view;
    const bool drop_shm = attempt == 0 && rejected->code == protocol::ErrorCode::SinkUnavailable &&
                          (view.sinks & protocol::sink::kShm) && view.sinks != protocol::sink::kShm;
    if (!drop_shm) throw RunError("the service rejected the view: " + describe_error(*rejected));
    if (warn) warn("service: " + describe_error(*rejected) + "; continuing without the shared-memory sink");
    view.sinks &= static_cast<std::uint8_t>(~protocol::sink::kShm);
  }
  return view;
}

std::optional<protocol::FrameReady> ClientSession::wait_frame(
    const protocol::Pose& pose, std::uint64_t pose_seq, std::chrono::milliseconds timeout,
    const std::function<void(const protocol::Error&)>& on_error,
    const std::function<void(const protocol::FrameReady&)>& on_other_frame) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    if (Clock::now() >= deadline && kept_.empty())
      throw RunError("no frame for the pose at sim time " + format_number(pose.sim_time_s) + " s within " +
                     std::to_string(timeout.count() / 1000) + " s (--frame-timeout)");
    std::optional<protocol::Message> m = next(deadline);
    if (!m) continue;
    if (auto* f = std::get_if<protocol::FrameReady>(&*m)) {
      if (f->request_id == 0 && same_pose(f->pose, pose)) return *f;
      if (on_other_frame) on_other_frame(*f);
    } else if (auto* e = std::get_if<protocol::Error>(&*m)) {
      if (on_error) on_error(*e);
      if (e->answers_seq == pose_seq || e->code == protocol::ErrorCode::RenderFailed) return std::nullopt;
    }
  }
}

}  // namespace cloudsvc::sim
