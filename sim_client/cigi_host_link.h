// The UDP link of `sim_client cigi` to an image generator: a socket connected to the IG's
// address (so only the IG's datagrams arrive, and the IG answers to the port the kernel
// chose), plain POSIX calls with a deadline on every wait.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/option_address.h"
#include "protocol/cigi/cigi_datagram.h"

namespace cloudsvc::sim {

class CigiHostLink {
 public:
  using Clock = std::chrono::steady_clock;

  // Throws RunError when the socket cannot be made or connected.
  explicit CigiHostLink(const cli::UdpEndpoint& ig);
  ~CigiHostLink();
  CigiHostLink(const CigiHostLink&) = delete;
  CigiHostLink& operator=(const CigiHostLink&) = delete;

  void send(const std::vector<std::uint8_t>& datagram);
  // The IG's next datagram, as read (cigi::read_ig_datagram), or nullopt at the deadline.
  // Throws RunError when the IG's machine reports that nothing listens at its address.
  std::optional<cigi::IgDatagram> receive(Clock::time_point deadline);

 private:
  int fd_ = -1;
  std::string ig_text_;
};

}  // namespace cloudsvc::sim
