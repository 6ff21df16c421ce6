// The CIGI 3.3 UDP endpoint of `cloudsvc serve --cigi` (docs/CIGI.md), on the network
// thread: every datagram received is read and checked (cigi::read_host_datagram) and handed
// on whole, bad ones included (their rejections become IG Messages); the IG's datagrams
// (Start of Frame and IG Messages, made by the render thread) go to --cigi-host, else to the
// address the host's last datagram came from. UDP never blocks the service: a send that
// fails is counted and the next frame's datagram goes out as usual.
#pragma once

#include <asio.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_datagram.h"
#include "service/serve_options.h"

namespace cloudsvc {

class CigiEndpoint {
 public:
  using Receive = std::function<void(cigi::HostDatagram datagram)>;

  // Binds options.listen (throws std::runtime_error "--cigi udp:...: <reason>").
  CigiEndpoint(asio::io_context& io, const CigiOptions& options, Receive receive);

  // The bound address, udp:HOST:PORT (the kernel's port for port 0).
  std::string bound_address() const;
  // Sends one IG -> host datagram; dropped (counted) while no host is known. Network thread.
  void send(std::vector<std::uint8_t> bytes);
  void stop();  // closes the socket; nothing is received or sent after

  std::uint64_t datagrams_received() const { return received_; }
  std::uint64_t datagrams_sent() const { return sent_; }
  std::uint64_t datagrams_not_sent() const { return not_sent_; }  // no host yet, or the send failed

 private:
  void receive_next();

  asio::ip::udp::socket socket_;
  Receive receive_;
  std::optional<asio::ip::udp::endpoint> fixed_host_;  // --cigi-host
  std::optional<asio::ip::udp::endpoint> last_sender_;
  asio::ip::udp::endpoint sender_;
  std::array<std::uint8_t, 65536> buffer_{};  // the largest UDP payload
  std::uint64_t received_ = 0, sent_ = 0, not_sent_ = 0;
  bool stopped_ = false;
};

}  // namespace cloudsvc
