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
    // A handshaken client that sends nothing for this long gets IdleTimeout and is dropped,
    // so idle connections cannot hold every --max-clients place; zero = never.
    std::chrono::milliseconds idle_timeout{60000};
    unsigned socket_mode = 0600;  // permissions of every Unix socket file
    // Per-client outbound queue (bytes of framed messages not yet taken by the socket;
    // docs/PROTOCOL.md, "Limits"): above max_queued_notice_bytes FrameReady notices are
    // dropped; a message that would take the queue above max_queued_bytes disconnects the
    // client instead (it sends requests but does not read the replies).
    std::size_t max_queued_notice_bytes = 1u << 20;  // 1 MiB
    std::size_t max_queued_bytes = 4u << 20;         // 4 MiB
  };

  // Binds every listen address (throws std::runtime_error naming the address on failure).
  // A Unix socket path where another process is listening is refused without touching it;
  // only a stale socket file (nobody accepts connections on it) is replaced. Socket files
  // are created with no access for others and then given config.socket_mode.
  NetworkServer(asio::io_context& io, Config config, Handler handler);
  ~NetworkServer();

  // Network thread only (use asio::post from other threads).
  void send_to(std::uint64_t client_id, const protocol::Message& m);
  void broadcast(const protocol::Message& m);
  void stop_listening();  // closes listeners, removes Unix socket files; sessions go on
  void stop();            // stop_listening, then closes every session

  std::size_t client_count() const { return sessions_.size(); }
  std::uint64_t notices_dropped() const { return notices_dropped_; }
  std::uint64_t clients_dropped_for_queue() const { return clients_dropped_for_queue_; }
  const Config& config() const { return config_; }
  // The bound addresses in listen order, as tcp://HOST:PORT (the kernel's port for port 0)
  // or unix:PATH.
  std::vector<std::string> bound_addresses() const;

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
