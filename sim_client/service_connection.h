// A client's connection to `cloudsvc serve` (docs/PROTOCOL.md): connect over TCP or a
// Unix socket, Hello/Welcome handshake, send messages, receive decoded messages with a
// timeout. Blocking, single-threaded (asio underneath).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "protocol/messages.h"

namespace cloudsvc::client {

// Connection-level failures: cannot connect, handshake refused, peer closed, framing
// error. what() is one line.
struct ConnectionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ServiceConnection {
 public:
  // address: "tcp://HOST:PORT" or "unix:PATH". Performs the handshake.
  ServiceConnection(const std::string& address, const std::string& client_name,
                    std::chrono::milliseconds timeout = std::chrono::milliseconds(5000),
                    std::uint32_t capabilities = protocol::capability::kAll);
  ~ServiceConnection();
  ServiceConnection(const ServiceConnection&) = delete;
  ServiceConnection& operator=(const ServiceConnection&) = delete;

  const protocol::Welcome& welcome() const;

  // Encodes, frames and writes m; returns its sequence number.
  std::uint64_t send(const protocol::Message& m);
  // Writes raw bytes (tests of malformed input).
  void send_raw(const std::uint8_t* data, std::size_t n);

  // The next message from the service, or nullopt after `timeout`. Throws
  // ConnectionError when the service closed the connection or broke the framing.
  std::optional<protocol::Message> receive(std::chrono::milliseconds timeout);

  // Receives until a message of type T arrives (others are passed to `other` if given),
  // or throws ConnectionError after `timeout`.
  template <class T>
  T receive_until(std::chrono::milliseconds timeout);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

template <class T>
T ServiceConnection::receive_until(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) throw ConnectionError("timed out waiting for the service");
    auto m = receive(left);
    if (m && std::holds_alternative<T>(*m)) return std::get<T>(*m);
  }
}

}  // namespace cloudsvc::client
