#include "service/network_server.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <stdexcept>
#include <variant>

#include "protocol/codec.h"
#include "protocol/framing.h"
#include "protocol/handshake.h"

namespace cloudsvc {

namespace {
using Tcp = asio::ip::tcp;
using Local = asio::local::stream_protocol;

bool is_frame_ready(const protocol::Message& m) { return std::holds_alternative<protocol::FrameReady>(m); }

// True when a process accepts connections on the Unix socket at path (a live service).
bool someone_listens(const std::string& path) {
  asio::io_context probe_io;
  Local::socket probe(probe_io);
  asio::error_code ec;
  probe.connect(Local::endpoint(path), ec);
  return !ec;  // ECONNREFUSED: a stale file nobody listens on
}

// Binds and listens on path with permissions `mode`. The socket is bound under a
// temporary name in the same folder while the umask denies group and others everything,
// given its mode, made to listen, and only then renamed to path: whoever sees the file at
// path can connect, and nobody but the owner could reach it before its mode was set.
std::unique_ptr<Local::acceptor> bind_unix_socket(asio::io_context& io, const std::string& path, unsigned mode) {
  std::error_code fec;
  if (std::filesystem::is_socket(path, fec)) {
    if (someone_listens(path))
      throw std::runtime_error("another process is listening on this socket; refusing to replace it "
                               "(stop that service first, or choose another path)");
    std::filesystem::remove(path, fec);  // stale socket file of a service that is gone
  }
  // sun_path holds 107 bytes: a path too long for the temporary suffix is bound directly.
  std::string bind_path = path + "." + std::to_string(::getpid()) + ".tmp";
  if (bind_path.size() > 107) bind_path = path;
  ::unlink(bind_path.c_str());  // a leftover of an earlier process with this pid
  auto acc = std::make_unique<Local::acceptor>(io);
  acc->open(Local());
  const mode_t old_umask = ::umask(077);  // single-threaded here: the render thread starts later
  asio::error_code ec;
  acc->bind(Local::endpoint(bind_path), ec);
  ::umask(old_umask);
  if (ec) throw std::runtime_error(ec.message());
  auto fail = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    ::unlink(bind_path.c_str());
    throw std::runtime_error(what + ": " + why);
  };
  if (::chmod(bind_path.c_str(), static_cast<mode_t>(mode)) != 0) fail("cannot set the socket's permissions");
  acc->listen(asio::socket_base::max_listen_connections, ec);
  if (ec) fail("listen: " + ec.message());
  if (bind_path != path && ::rename(bind_path.c_str(), path.c_str()) != 0) fail("cannot move the socket into place");
  return acc;
}
}  // namespace

// One connected client. Lives on the network thread; owned by the server's session map
// and kept alive by pending asynchronous operations.
class ClientSession : public std::enable_shared_from_this<ClientSession> {
 public:
  using Socket = std::variant<Tcp::socket, Local::socket>;

  ClientSession(NetworkServer& server, std::uint64_t id, Socket socket)
      : server_(server), id_(id), socket_(std::move(socket)), timer_(server.io_), idle_timer_(server.io_),
        decoder_(server.config_.welcome.limits.max_payload_bytes) {}

  std::uint64_t id() const { return id_; }
  bool handshaken() const { return handshaken_; }

  void start() {
    timer_.expires_after(server_.config_.handshake_timeout);
    timer_.async_wait([self = shared_from_this()](const asio::error_code& ec) {
      if (!ec && !self->handshaken_) self->close();  // connected but never said Hello
    });
    read();
  }

  // Queues m. FrameReady notices are dropped when the client does not keep up; any other
  // message that would overflow the queue's bound closes the connection.
  void send(const protocol::Message& m) {
    if (closing_) return;
    const NetworkServer::Config& cfg = server_.config_;
    if (is_frame_ready(m) && queued_bytes_ > cfg.max_queued_notice_bytes) {
      ++server_.notices_dropped_;
      return;
    }
    auto bytes = std::make_shared<std::vector<std::uint8_t>>(protocol::frame(protocol::encode(m, next_seq_++)));
    if (queued_bytes_ + bytes->size() > cfg.max_queued_bytes) {
      ++server_.clients_dropped_for_queue_;
      std::printf("cloudsvc serve: client %llu disconnected: more than %zu bytes of replies queued (it does not read)\n",
                  static_cast<unsigned long long>(id_), cfg.max_queued_bytes);
      std::fflush(stdout);
      close();
      return;
    }
    queued_bytes_ += bytes->size();
    queue_.push_back(std::move(bytes));
    if (queue_.size() == 1) write_next();
  }

  // Sends m, then closes (fatal errors).
  void send_and_close(const protocol::Message& m) {
    send(m);
    close_after_write_ = true;
    if (queue_.empty()) close();
  }

  void close() {
    if (closing_) return;
    closing_ = true;
    timer_.cancel();
    idle_timer_.cancel();
    std::visit([](auto& s) {
      asio::error_code ec;
      s.shutdown(asio::socket_base::shutdown_both, ec);
      s.close(ec);
    }, socket_);
    server_.session_closed(id_);
  }

 private:
  void read() {
    auto self = shared_from_this();
    std::visit([&](auto& s) {
      s.async_read_some(asio::buffer(buffer_), [self](const asio::error_code& ec, std::size_t n) {
        if (ec) {  // EOF, reset, killed mid-message: drop this client only
          self->close();
          return;
        }
        self->on_bytes(n);
      });
    }, socket_);
  }

  void on_bytes(std::size_t n) {
    if (closing_) return;
    decoder_.feed(std::span<const std::uint8_t>(buffer_.data(), n));
    while (auto payload = decoder_.next()) {
      on_payload(*payload);
      if (closing_ || close_after_write_) return;
    }
    if (decoder_.failed()) {
      send_and_close(protocol::Error{protocol::ErrorCode::FramingError, decoder_.error_text(), 0});
      return;
    }
    read();
  }

  void on_payload(const std::vector<std::uint8_t>& payload) {
    const protocol::DecodeResult r = protocol::decode(payload);
    if (!handshaken_) {
      const protocol::HelloVerdict v = protocol::answer_first_message(r, server_.config_.welcome);
      if (!v.accepted) {
        send_and_close(v.reply);
        return;
      }
      handshaken_ = true;
      timer_.cancel();
      send(v.reply);
      arm_idle_timer();
      return;
    }
    arm_idle_timer();  // any message, valid or not, shows the client is alive
    if (!r.ok()) {
      send(r.to_error());  // the client's state is untouched; it may go on
      return;
    }
    if (auto err = protocol::check_client_message(*r.message, r.seq, server_.config_.welcome.capabilities)) {
      send(*err);
      return;
    }
    server_.handler_(id_, *r.message, r.seq);
  }

  // (Re)starts the idle countdown; on expiry the client gets IdleTimeout and is dropped.
  void arm_idle_timer() {
    const auto timeout = server_.config_.idle_timeout;
    if (timeout.count() <= 0 || closing_) return;
    idle_timer_.expires_after(timeout);
    idle_timer_.async_wait([self = shared_from_this(), timeout](const asio::error_code& ec) {
      if (ec || self->closing_ || self->close_after_write_) return;  // re-armed, closed or already leaving
      const auto s = std::chrono::duration_cast<std::chrono::seconds>(timeout).count();
      self->send_and_close(protocol::Error{protocol::ErrorCode::IdleTimeout,
                                           "no message for " + std::to_string(s) +
                                               " s (idle timeout); send a StatsRequest to stay connected",
                                           0});
    });
  }

  void write_next() {
    auto self = shared_from_this();
    auto bytes = queue_.front();
    std::visit([&](auto& s) {
      asio::async_write(s, asio::buffer(*bytes), [self, bytes](const asio::error_code& ec, std::size_t) {
        self->queued_bytes_ -= bytes->size();
        self->queue_.pop_front();
        if (ec) {
          self->close();
          return;
        }
        if (!self->queue_.empty()) self->write_next();
        else if (self->close_after_write_) self->close();
      });
    }, socket_);
  }

  NetworkServer& server_;
  std::uint64_t id_;
  Socket socket_;
  asio::steady_timer timer_;       // handshake deadline
  asio::steady_timer idle_timer_;  // idle deadline after the handshake
  protocol::FrameDecoder decoder_;
  std::array<std::uint8_t, 65536> buffer_{};
  std::deque<std::shared_ptr<std::vector<std::uint8_t>>> queue_;
  std::size_t queued_bytes_ = 0;
  std::uint64_t next_seq_ = 1;
  bool handshaken_ = false;
  bool closing_ = false;
  bool close_after_write_ = false;
};

NetworkServer::NetworkServer(asio::io_context& io, Config config, Handler handler)
    : io_(io), config_(std::move(config)), handler_(std::move(handler)) {
  for (const ListenAddress& a : config_.listen) {
    try {
      if (a.kind == ListenAddress::Kind::Tcp) {
        const Tcp::endpoint ep(asio::ip::make_address(a.host), a.port);
        auto acc = std::make_unique<Tcp::acceptor>(io_);
        acc->open(ep.protocol());
        acc->set_option(asio::socket_base::reuse_address(true));
        acc->bind(ep);
        acc->listen();
        tcp_.push_back(std::move(acc));
      } else {
        unix_.push_back(bind_unix_socket(io_, a.path, config_.socket_mode));
        unix_paths_.push_back(a.path);
      }
    } catch (const std::exception& e) {
      for (const std::string& p : unix_paths_) ::unlink(p.c_str());  // the ones this service created
      throw std::runtime_error("--listen " + a.text + ": " + e.what());
    }
  }
  for (std::size_t i = 0; i < tcp_.size(); ++i) accept_tcp(i);
  for (std::size_t i = 0; i < unix_.size(); ++i) accept_unix(i);
}

NetworkServer::~NetworkServer() { stop(); }

void NetworkServer::accept_tcp(std::size_t i) {
  tcp_[i]->async_accept([this, i](const asio::error_code& ec, Tcp::socket s) {
    if (stopped_) return;
    if (!ec) {
      s.set_option(Tcp::no_delay(true));
      start_session(std::make_shared<ClientSession>(*this, next_id_++, ClientSession::Socket(std::move(s))));
    }
    accept_tcp(i);
  });
}

void NetworkServer::accept_unix(std::size_t i) {
  unix_[i]->async_accept([this, i](const asio::error_code& ec, Local::socket s) {
    if (stopped_) return;
    if (!ec) start_session(std::make_shared<ClientSession>(*this, next_id_++, ClientSession::Socket(std::move(s))));
    accept_unix(i);
  });
}

void NetworkServer::start_session(std::shared_ptr<ClientSession> s) {
  if (static_cast<int>(sessions_.size()) >= config_.max_clients) {
    sessions_[s->id()] = s;
    s->send_and_close(protocol::Error{protocol::ErrorCode::Busy,
                                      "too many clients (" + std::to_string(config_.max_clients) + ")", 0});
    return;
  }
  sessions_[s->id()] = s;
  s->start();
}

void NetworkServer::session_closed(std::uint64_t id) { sessions_.erase(id); }

std::vector<std::string> NetworkServer::bound_addresses() const {
  std::vector<std::string> out;
  std::size_t t = 0, u = 0;
  for (const ListenAddress& a : config_.listen) {
    if (a.kind == ListenAddress::Kind::Tcp) {
      asio::error_code ec;
      const Tcp::endpoint ep = tcp_[t++]->local_endpoint(ec);
      const std::string host = ep.address().is_v6() ? "[" + ep.address().to_string() + "]" : ep.address().to_string();
      out.push_back("tcp://" + host + ":" + std::to_string(ep.port()));
    } else {
      out.push_back("unix:" + unix_paths_[u++]);
    }
  }
  return out;
}

void NetworkServer::send_to(std::uint64_t client_id, const protocol::Message& m) {
  auto it = sessions_.find(client_id);
  if (it == sessions_.end()) return;
  const std::shared_ptr<ClientSession> s = it->second;  // a send may close and erase it
  if (s->handshaken()) s->send(m);
}

void NetworkServer::broadcast(const protocol::Message& m) {
  // Copy: a send may close a session, which erases it from the map.
  std::vector<std::shared_ptr<ClientSession>> all;
  for (auto& [id, s] : sessions_) all.push_back(s);
  for (auto& s : all)
    if (s->handshaken()) s->send(m);
}

void NetworkServer::stop_listening() {
  if (stopped_) return;
  stopped_ = true;
  asio::error_code ec;
  for (auto& a : tcp_) a->close(ec);
  for (auto& a : unix_) a->close(ec);
  for (const std::string& p : unix_paths_) ::unlink(p.c_str());
}

void NetworkServer::stop() {
  stop_listening();
  std::vector<std::shared_ptr<ClientSession>> all;
  for (auto& [id, s] : sessions_) all.push_back(s);
  for (auto& s : all) s->close();
}

}  // namespace cloudsvc
