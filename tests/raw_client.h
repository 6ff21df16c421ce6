// A bare protocol client for service tests (Unix socket or loopback TCP): writes arbitrary
// bytes, reads and decodes replies with a timeout, and tells when the service hung up.
#pragma once

#include <gtest/gtest.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/codec.h"
#include "protocol/framing.h"

namespace cloudsvc::test {

class RawClient {
 public:
  // Connects to the Unix socket `path`.
  explicit RawClient(const std::string& path) {
    fd_ = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::strncpy(a.sun_path, path.c_str(), sizeof a.sun_path - 1);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
  }
  // Connects to 127.0.0.1:port.
  explicit RawClient(int tcp_port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<std::uint16_t>(tcp_port));
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
    const int one = 1;
    ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  }
  RawClient(RawClient&& o) noexcept : fd_(o.fd_), connected_(o.connected_), decoder_(std::move(o.decoder_)) { o.fd_ = -1; }
  RawClient(const RawClient&) = delete;
  ~RawClient() { close(); }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  bool connected() const { return connected_; }
  int fd() const { return fd_; }
  void write(const std::vector<std::uint8_t>& b) {
    ASSERT_EQ(::send(fd_, b.data(), b.size(), MSG_NOSIGNAL), static_cast<ssize_t>(b.size()));
  }
  // Writes without asserting; false when the peer is gone (EPIPE, ECONNRESET).
  bool try_write(const std::vector<std::uint8_t>& b) {
    std::size_t done = 0;
    while (done < b.size()) {
      const ssize_t n = ::send(fd_, b.data() + done, b.size() - done, MSG_NOSIGNAL);
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }
  void send(const protocol::Message& m, std::uint64_t seq) { write(protocol::frame(protocol::encode(m, seq))); }
  // Next decoded message, or nullopt on timeout; `closed` set when the service hung up.
  std::optional<protocol::Message> receive(std::chrono::milliseconds timeout, bool* closed = nullptr) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      if (auto p = decoder_.next()) {
        auto r = protocol::decode(*p);
        if (r.ok()) return r.message;
        continue;
      }
      const int left = static_cast<int>(
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count());
      if (left <= 0) return std::nullopt;
      pollfd pfd{fd_, POLLIN, 0};
      if (::poll(&pfd, 1, left) <= 0) return std::nullopt;
      std::uint8_t buf[4096];
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        if (closed) *closed = true;
        return std::nullopt;
      }
      decoder_.feed(std::span<const std::uint8_t>(buf, static_cast<std::size_t>(n)));
    }
  }
  // True when the service closed the connection within `timeout`.
  bool closed_by_service(std::chrono::milliseconds timeout) {
    bool closed = false;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!closed && std::chrono::steady_clock::now() < deadline) receive(std::chrono::milliseconds(100), &closed);
    return closed;
  }

 private:
  int fd_ = -1;
  bool connected_ = false;
  protocol::FrameDecoder decoder_;
};

// The next Error within ~10 s (other messages skipped); a test failure if none comes.
inline protocol::Error expect_error(RawClient& c) {
  for (int i = 0; i < 50; ++i) {
    auto m = c.receive(std::chrono::milliseconds(200));
    if (m && std::holds_alternative<protocol::Error>(*m)) return std::get<protocol::Error>(*m);
  }
  ADD_FAILURE() << "no Error received";
  return {};
}

// Says Hello (seq 1) and expects Welcome.
inline void handshake(RawClient& c) {
  EXPECT_TRUE(c.connected());
  protocol::Hello h;
  h.client_name = "raw";
  c.send(h, 1);
  auto w = c.receive(std::chrono::seconds(10));
  EXPECT_TRUE(w && std::holds_alternative<protocol::Welcome>(*w));
}

}  // namespace cloudsvc::test
