// One soak connection on a shared io_context (soak_client.h).
#include "sim_client/soak_client.h"

#include <algorithm>

#include "protocol/codec.h"
#include "sim_client/client_session.h"
#include "sim_client/connection_failure.h"
#include "sim_client/pacing.h"
#include "sim_client/service_address.h"

namespace cloudsvc::sim {

namespace {

using Generic = asio::generic::stream_protocol;

// Unsent bytes beyond which due poses are skipped instead of queued: the service is not
// reading (a pose is ~200 bytes, so 1 MiB is seconds of poses even at 1000 Hz), and
// queueing more would only measure the client's own backlog.
constexpr std::size_t kMaxQueuedBytes = std::size_t{1} << 20;
// Own poses waiting for a frame are forgotten after this (latest wins: most never get
// one; this bounds the memory when a client's poses keep being superseded).
constexpr auto kKeepOutstanding = std::chrono::seconds(60);
// A late timer catches up at most this much schedule in one go, so that one slow wake-up
// does not turn into a burst of thousands of poses.
constexpr double kMaxCatchUp_s = 0.1;

double ms_between(SoakClient::Clock::time_point a, SoakClient::Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

SoakClient::SoakClient(asio::io_context& io, std::string address, SoakClientPlan plan)
    : strand_(asio::make_strand(io)), socket_(strand_), timer_(strand_), address_(std::move(address)),
      plan_(std::move(plan)) {
  stats_.address = address_;
}

std::future<std::string> SoakClient::connect(std::chrono::milliseconds timeout) {
  std::future<std::string> f = connected_.get_future();
  asio::post(strand_, [self = shared_from_this(), timeout] { self->start_connect(timeout); });
  return f;
}

void SoakClient::start_connect(std::chrono::milliseconds timeout) {
  Generic::endpoint endpoint;
  bool tcp = false;
  try {
    const client::ServiceAddress a = client::parse_service_address(address_);
    if (a.kind == client::ServiceAddress::Kind::Tcp) {
      asio::error_code ec;
      const asio::ip::address host = asio::ip::make_address(a.host, ec);
      if (ec) throw std::runtime_error(address_ + ": bad host: " + ec.message());
      endpoint = Generic::endpoint(asio::ip::tcp::endpoint(host, a.port));
      tcp = true;
    } else {
      endpoint = Generic::endpoint(asio::local::stream_protocol::endpoint(a.path));
    }
  } catch (const std::exception& e) {
    fail_connect(e.what());
    return;
  }
  state_ = State::Connecting;
  timer_.expires_after(timeout);
  timer_.async_wait([self = shared_from_this(), timeout](const asio::error_code& ec) {
    if (!ec && (self->state_ == State::Connecting || self->state_ == State::Handshake))
      self->fail_connect(self->address_ + ": no Welcome within " +
                         std::to_string(std::chrono::duration_cast<std::chrono::seconds>(timeout).count()) + " s");
  });
  socket_.async_connect(endpoint, [self = shared_from_this(), tcp](const asio::error_code& ec) {
    self->on_connected(ec, tcp);
  });
}

void SoakClient::on_connected(const asio::error_code& ec, bool tcp) {
  if (state_ != State::Connecting) return;  // timed out meanwhile
  if (ec) {
    fail_connect(address_ + ": " + ec.message());
    return;
  }
  if (tcp) {
    asio::error_code ignore;
    socket_.set_option(asio::ip::tcp::no_delay(true), ignore);  // poses are small; latency matters
  }
  state_ = State::Handshake;
  protocol::Hello hello;
  hello.client_name = "sim_client soak " + std::to_string(plan_.index);
  hello.capabilities = protocol::capability::kAll;
  send(hello);
  read();
}

void SoakClient::fail_connect(const std::string& problem) {
  if (!connected_done_) {
    connected_done_ = true;
    connected_.set_value(problem);
  }
  shut();
}

std::uint64_t SoakClient::send(const protocol::Message& m) {
  const std::uint64_t seq = next_seq_++;
  auto bytes = std::make_shared<std::vector<std::uint8_t>>(protocol::frame(protocol::encode(m, seq)));
  queued_bytes_ += bytes->size();
  queue_.push_back(std::move(bytes));
  if (writing_.empty()) write_next();
  return seq;
}

// Writes everything queued in one gathered write.
void SoakClient::write_next() {
  if (queue_.empty() || state_ == State::Closed) return;
  std::vector<asio::const_buffer> buffers;
  for (Bytes& b : queue_) {
    buffers.push_back(asio::buffer(*b));
    writing_.push_back(std::move(b));
  }
  queue_.clear();
  asio::async_write(socket_, buffers, [self = shared_from_this()](const asio::error_code& ec, std::size_t) {
    if (self->state_ == State::Closed) return;
    if (ec) {
      self->lost(client::connection_failure_text("send", ec));
      return;
    }
    for (const Bytes& b : self->writing_) self->queued_bytes_ -= b->size();
    self->writing_.clear();
    self->write_next();
  });
}

void SoakClient::read() {
  socket_.async_read_some(asio::buffer(buffer_), [self = shared_from_this()](const asio::error_code& ec, std::size_t n) {
    self->on_read(ec, n);
  });
}

void SoakClient::on_read(const asio::error_code& ec, std::size_t n) {
  if (state_ == State::Closed) return;
  if (ec) {
    lost(client::connection_failure_text("receive", ec));
    return;
  }
  decoder_.feed(std::span<const std::uint8_t>(buffer_.data(), n));
  while (auto payload = decoder_.next()) {
    protocol::DecodeResult r = protocol::decode(*payload);
    if (!r.ok()) {
      lost("undecodable message from the service: " + r.error_text);
      return;
    }
    handle(*r.message);
    if (state_ == State::Closed) return;
  }
  if (decoder_.failed()) {
    lost("framing error from the service: " + decoder_.error_text());
    return;
  }
  read();
}

void SoakClient::handle(protocol::Message& m) {
  if (state_ == State::Handshake) {
    if (auto* w = std::get_if<protocol::Welcome>(&m)) {
      if (w->major != protocol::kProtocolMajor) {
        fail_connect(address_ + ": protocol major " + std::to_string(w->major) + ", this client speaks " +
                     std::to_string(protocol::kProtocolMajor));
        return;
      }
      welcome_ = *w;
      state_ = State::Ready;
      timer_.cancel();
      connected_done_ = true;
      connected_.set_value("");
    } else if (auto* e = std::get_if<protocol::Error>(&m)) {
      fail_connect(address_ + ": refused: " + describe_error(*e));
    } else {
      fail_connect(address_ + ": first message was " + std::string(protocol::message_name(m)) + ", not Welcome");
    }
    return;
  }
  const Clock::time_point now = Clock::now();
  if (auto* f = std::get_if<protocol::FrameReady>(&m)) {
    on_frame(*f, now);
  } else if (auto* e = std::get_if<protocol::Error>(&m)) {
    if (sync_ && sync_seqs_.count(e->answers_seq)) {
      sync_result_.errors.push_back(*e);  // the caller's to judge
      return;
    }
    ++stats_.errors[std::string(protocol::error_code_name(e->code))];
    // A refused RenderRequest (e.g. Overloaded) gets no frame: it is answered.
    for (auto it = requests_.begin(); it != requests_.end(); ++it)
      if (e->answers_seq != 0 && it->second.seq == e->answers_seq) {
        requests_.erase(it);
        finish_if_drained();
        break;
      }
  } else if (auto* s = std::get_if<protocol::Stats>(&m)) {
    on_stats(*s);
  }
}

void SoakClient::on_frame(const protocol::FrameReady& f, Clock::time_point now) {
  if (state_ != State::Flying && state_ != State::Draining) {  // before the run: only the warm-up counts
    // Any frame after the warm-up pose will do: the service has rendered since (another
    // host's newer pose may have superseded ours).
    if (warm_) {
      warm_->set_value(ms_between(warm_sent_, now));
      warm_.reset();
    }
    return;
  }
  ++stats_.frames;
  frames_live_.fetch_add(1, std::memory_order_relaxed);
  if (f.request_id != 0) {  // answers a RenderRequest: only the requester gets it
    const auto it = requests_.find(f.request_id);
    if (it == requests_.end()) return;
    ++stats_.request_frames;
    stats_.request_latency_ms.push_back(ms_between(it->second.sent, now));
    requests_.erase(it);
    finish_if_drained();
    return;
  }
  stats_.frame_numbers.push_back(f.frame_number);
  // Own poses are in sim-time order; the echo is exactly the pose sent (flags aside).
  const auto it = std::lower_bound(outstanding_.begin(), outstanding_.end(), f.pose.sim_time_s,
                                   [](const Outstanding& o, double t) { return o.pose.sim_time_s < t; });
  if (it == outstanding_.end() || !same_pose(f.pose, it->pose)) return;  // another client's pose
  ++stats_.own_frames;
  stats_.latency_ms.push_back(ms_between(it->sent, now));
  stats_.service_latency_ms.push_back(f.latency_ms);
  // Latest wins: an older pose of this client can no longer be rendered.
  outstanding_.erase(outstanding_.begin(), it + 1);
}

void SoakClient::on_stats(const protocol::Stats& s) {
  if (sync_) {
    sync_result_.stats = s;
    sync_->set_value(std::move(sync_result_));
    sync_.reset();
    sync_seqs_.clear();
    sync_result_ = {};
    return;
  }
  if (state_ == State::Draining) {
    final_stats_ = s;
    stats_.final_stats = true;
    finish_if_drained();
  }
}

// Done once the closing Stats came and no RenderRequest waits for its answer: the run's
// end, not a disconnect.
void SoakClient::finish_if_drained() {
  if (state_ == State::Draining && stats_.final_stats && requests_.empty()) shut();
}

std::future<SoakSyncResult> SoakClient::sync(std::vector<protocol::Message> messages) {
  auto promise = std::make_shared<std::promise<SoakSyncResult>>();
  std::future<SoakSyncResult> f = promise->get_future();
  asio::post(strand_, [self = shared_from_this(), promise, messages = std::move(messages)] {
    if (self->state_ != State::Ready) {
      promise->set_value(SoakSyncResult{});
      return;
    }
    self->sync_.emplace(std::move(*promise));
    for (const protocol::Message& m : messages) self->sync_seqs_.insert(self->send(m));
    self->send(protocol::StatsRequest{});
  });
  return f;
}

std::future<std::optional<double>> SoakClient::warm_up(const protocol::Pose& pose) {
  auto promise = std::make_shared<std::promise<std::optional<double>>>();
  std::future<std::optional<double>> f = promise->get_future();
  asio::post(strand_, [self = shared_from_this(), promise, pose] {
    if (self->state_ != State::Ready) {
      promise->set_value(std::nullopt);
      return;
    }
    self->warm_.emplace(std::move(*promise));
    self->warm_sent_ = Clock::now();
    self->send(pose);
  });
  return f;
}

std::future<void> SoakClient::fly(Clock::time_point start, Clock::time_point end) {
  std::future<void> f = flown_.get_future();
  asio::post(strand_, [self = shared_from_this(), start, end] {
    self->flying_started_ = true;
    if (self->state_ != State::Ready) {
      self->finish_promises();
      return;
    }
    self->state_ = State::Flying;
    self->start_ = start;
    self->end_ = end;
    self->timer_.expires_at(start);
    self->timer_.async_wait([self](const asio::error_code& ec) { self->tick(ec); });
  });
  return f;
}

std::chrono::steady_clock::time_point soak_pose_due(std::chrono::steady_clock::time_point start,
                                                    std::chrono::steady_clock::time_point end, std::uint64_t k,
                                                    double rate_hz) {
  const double offset_s = static_cast<double>(k) / rate_hz;            // s after start
  const double span_s = std::chrono::duration<double>(end - start).count();  // s, the run
  if (!(offset_s < span_s)) return end;  // also inf and NaN: never cast to the clock
  return due_after(start, offset_s);
}

SoakClient::Clock::time_point SoakClient::due(std::uint64_t k) const {
  return soak_pose_due(start_, end_, k, plan_.rate_hz);
}

// Sends the poses due by now (at most kMaxCatchUp_s of schedule per wake-up), then sleeps
// until the next is due. Every pose due before `end` is sent, a late timer only sends it
// late: a run sends ceil(duration x rate) poses. After the last, the StatsRequest at `end`.
void SoakClient::tick(const asio::error_code& ec) {
  if (ec || state_ != State::Flying) return;
  const Clock::time_point now = Clock::now();
  const auto burst = static_cast<std::uint64_t>(std::max(1.0, plan_.rate_hz * kMaxCatchUp_s));
  for (std::uint64_t n = 0; n < burst && due(next_pose_) <= now && due(next_pose_) < end_; ++n) send_pose(now);
  const Clock::time_point next = due(next_pose_);
  if (next >= end_ && now >= end_) {
    state_ = State::Draining;
    send(protocol::StatsRequest{});  // its answer ends this client (on_stats)
    return;
  }
  timer_.expires_at(next >= end_ ? end_ : std::max(next, now));  // behind schedule: at once
  timer_.async_wait([self = shared_from_this()](const asio::error_code& e) { self->tick(e); });
}

void SoakClient::send_pose(Clock::time_point now) {
  const std::uint64_t k = next_pose_++;
  protocol::Pose pose = plan_.track.pose(plan_.index, static_cast<double>(k) / plan_.rate_hz);
  if (k == 0) pose.flags = protocol::pose_flag::kTeleport;  // no history from whatever was shown before
  if (queued_bytes_ > kMaxQueuedBytes) {
    ++stats_.poses_skipped;
    return;
  }
  send(pose);
  ++stats_.poses_sent;
  poses_live_.fetch_add(1, std::memory_order_relaxed);
  outstanding_.push_back({pose, now});
  while (!outstanding_.empty() && now - outstanding_.front().sent > kKeepOutstanding) outstanding_.pop_front();
  if (plan_.render_every > 0 && (k + 1) % plan_.render_every == 0) {
    // Ids unique per client and never 0: the client number in the high bits.
    const std::uint64_t id = (static_cast<std::uint64_t>(plan_.index + 1) << 40) | ++requests_made_;
    requests_[id] = PendingRequest{send(protocol::RenderRequest{id}), now};
    ++stats_.requests_sent;
  }
}

void SoakClient::lost(const std::string& reason) {
  if (state_ == State::Closed) return;
  if (state_ == State::Connecting || state_ == State::Handshake) {
    fail_connect(address_ + ": " + reason);
    return;
  }
  stats_.disconnected = true;
  stats_.disconnect_reason = reason;
  shut();
}

void SoakClient::close() {
  asio::post(strand_, [self = shared_from_this()] { self->shut(); });
}

// Closes the socket (pending handlers see state Closed and stop) and makes every open
// future ready.
void SoakClient::shut() {
  if (state_ != State::Closed) {
    state_ = State::Closed;
    asio::error_code ignore;
    timer_.cancel();
    socket_.close(ignore);
  }
  finish_promises();
}

void SoakClient::finish_promises() {
  if (!connected_done_) {
    connected_done_ = true;
    connected_.set_value(address_ + ": connection closed");
  }
  if (sync_) {
    sync_->set_value(std::move(sync_result_));
    sync_.reset();
  }
  if (warm_) {
    warm_->set_value(std::nullopt);
    warm_.reset();
  }
  if (flying_started_ && !flown_done_) {
    flown_done_ = true;
    flown_.set_value();
  }
}

}  // namespace cloudsvc::sim
