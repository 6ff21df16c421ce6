// The service's sockets (asio, one network thread): TCP and Unix stream listeners,
// one session per client with the handshake, framing, decoding and validation of
// docs/PROTOCOL.md. Valid client messages go to a handler; bad ones get an Error (or, when
// fatal, a disconnect) for that client only. Outgoing messages are queued per client and
// never block: a slow client loses FrameReady notices (counted), not the service, and a
// client whose queue of other replies outgrows its bound is disconnected (counted).
#pragma once

#include <asio.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "protocol/messages.h"
#include "service/serve_options.h"

namespace cloudsvc {

class ClientSession;

class NetworkServer {
 public:
  // Called on the network thread for every valid, handshaken client message.
  using Handler = std::function<void(std::uint64_t client_id, const protocol::Message& m, std::uint64_t seq)>;

  struct Config {
    std::vector<ListenAddress> listen;
    protocol::Welcome welcome;
    int max_clients = 16;
    std::chrono::milliseconds handshake_timeout{10000};  // a client that sends no Hello is dropped
    // Per-client outbound queue (bytes of framed messages not yet taken by the socket;
    // docs/PROTOCOL.md, "Limits"): above max_queued_notice_bytes FrameReady notices are
    // dropped; a message that would take the queue above max_queued_bytes disconnects the
    // client instead (it sends requests but does not read the replies).
    std::size_t max_queued_notice_bytes = 1u << 20;  // 1 MiB
    std::size_t max_queued_bytes = 4u << 20;         // 4 MiB
  };

  // Binds every listen address (throws std::runtime_error naming the address on failure).
  NetworkServer(asio::io_context& io, Config config, Handler handler);
  ~NetworkServer();

  // Network thread only (use asio::post from other threads).
  void send_to(std::uint64_t client_id, const protocol::Message& m);
  void broadcast(const protocol::Message& m);
  void stop();  // closes listeners and sessions, removes Unix socket files

  std::size_t client_count() const { return sessions_.size(); }
  std::uint64_t notices_dropped() const { return notices_dropped_; }
  std::uint64_t clients_dropped_for_queue() const { return clients_dropped_for_queue_; }
  const Config& config() const { return config_; }

 private:
  friend class ClientSession;
  void accept_tcp(std::size_t i);
  void accept_unix(std::size_t i);
  void start_session(std::shared_ptr<ClientSession> s);
  void session_closed(std::uint64_t id);

  asio::io_context& io_;
  Config config_;
  Handler handler_;
  std::vector<std::unique_ptr<asio::ip::tcp::acceptor>> tcp_;
  std::vector<std::unique_ptr<asio::local::stream_protocol::acceptor>> unix_;
  std::vector<std::string> unix_paths_;
  std::map<std::uint64_t, std::shared_ptr<ClientSession>> sessions_;
  std::uint64_t next_id_ = 1;
  std::uint64_t notices_dropped_ = 0;
  std::uint64_t clients_dropped_for_queue_ = 0;
  bool stopped_ = false;
};

}  // namespace cloudsvc
