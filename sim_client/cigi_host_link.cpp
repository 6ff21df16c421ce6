// The UDP link to an image generator (cigi_host_link.h).
#include "sim_client/cigi_host_link.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

CigiHostLink::CigiHostLink(const cli::UdpEndpoint& ig) : ig_text_(ig.text()) {
  sockaddr_storage addr{};
  socklen_t len = 0;
  const bool v6 = ig.host.find(':') != std::string::npos;
  if (v6) {
    auto* a = reinterpret_cast<sockaddr_in6*>(&addr);
    a->sin6_family = AF_INET6;
    a->sin6_port = htons(ig.port);
    inet_pton(AF_INET6, ig.host.c_str(), &a->sin6_addr);
    len = sizeof(sockaddr_in6);
  } else {
    auto* a = reinterpret_cast<sockaddr_in*>(&addr);
    a->sin_family = AF_INET;
    a->sin_port = htons(ig.port);
    inet_pton(AF_INET, ig.host.c_str(), &a->sin_addr);
    len = sizeof(sockaddr_in);
  }
  fd_ = ::socket(v6 ? AF_INET6 : AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw RunError("cannot make a UDP socket: " + std::string(std::strerror(errno)));
  if (::connect(fd_, reinterpret_cast<const sockaddr*>(&addr), len) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw RunError("--ig " + ig_text_ + ": " + why);
  }
}

CigiHostLink::~CigiHostLink() {
  if (fd_ >= 0) ::close(fd_);
}

void CigiHostLink::send(const std::vector<std::uint8_t>& datagram) {
  // A refused earlier datagram (ICMP) is reported on the next call; receive() reports it.
  if (::send(fd_, datagram.data(), datagram.size(), 0) < 0 && errno != ECONNREFUSED)
    throw RunError("--ig " + ig_text_ + ": cannot send: " + std::string(std::strerror(errno)));
}

std::optional<cigi::IgDatagram> CigiHostLink::receive(Clock::time_point deadline) {
  std::vector<std::uint8_t> buffer(65536);
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) throw RunError("poll: " + std::string(std::strerror(errno)));
    if (ready <= 0) continue;
    const ssize_t n = ::recv(fd_, buffer.data(), buffer.size(), 0);
    if (n >= 0) return cigi::read_ig_datagram(std::span<const std::uint8_t>(buffer.data(), static_cast<std::size_t>(n)));
    if (errno == ECONNREFUSED)
      throw RunError("--ig " + ig_text_ + ": nothing receives there (the datagram was refused; is `cloudsvc serve --cigi` running?)");
    if (errno != EINTR && errno != EAGAIN) throw RunError("recv: " + std::string(std::strerror(errno)));
  }
}

}  // namespace cloudsvc::sim
