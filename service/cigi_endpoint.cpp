// The CIGI UDP endpoint (cigi_endpoint.h).
#include "service/cigi_endpoint.h"

#include <memory>
#include <stdexcept>

namespace cloudsvc {

namespace {

asio::ip::udp::endpoint udp_endpoint(const cli::UdpEndpoint& e) {
  return {asio::ip::make_address(e.host), e.port};
}

}  // namespace

CigiEndpoint::CigiEndpoint(asio::io_context& io, const CigiOptions& options, Receive receive)
    : socket_(io), receive_(std::move(receive)) {
  const asio::ip::udp::endpoint local = udp_endpoint(options.listen);
  asio::error_code ec;
  socket_.open(local.protocol(), ec);
  if (!ec) socket_.bind(local, ec);
  if (ec) throw std::runtime_error("--cigi " + options.listen.text() + ": cannot bind: " + ec.message());
  if (options.host) fixed_host_ = udp_endpoint(*options.host);
  receive_next();
}

std::string CigiEndpoint::bound_address() const {
  asio::error_code ec;
  const asio::ip::udp::endpoint local = socket_.local_endpoint(ec);
  if (ec) return "udp:?";
  cli::UdpEndpoint e;
  e.host = local.address().to_string();
  e.port = local.port();
  return e.text();
}

void CigiEndpoint::receive_next() {
  socket_.async_receive_from(asio::buffer(buffer_), sender_, [this](const asio::error_code& ec, std::size_t n) {
    if (stopped_ || ec == asio::error::operation_aborted) return;
    if (!ec) {
      // Every datagram, usable or not, names the host: its answers (IG Messages) go back there.
      ++received_;
      last_sender_ = sender_;
      receive_(cigi::read_host_datagram(std::span<const std::uint8_t>(buffer_.data(), n)));
    }
    // An error here (e.g. ICMP port unreachable reported for an earlier send) ends
    // nothing: the next datagram is awaited.
    receive_next();
  });
}

void CigiEndpoint::send(std::vector<std::uint8_t> bytes) {
  const std::optional<asio::ip::udp::endpoint>& to = fixed_host_ ? fixed_host_ : last_sender_;
  if (stopped_ || !to) {
    ++not_sent_;
    return;
  }
  auto data = std::make_shared<std::vector<std::uint8_t>>(std::move(bytes));
  socket_.async_send_to(asio::buffer(*data), *to, [this, data](const asio::error_code& ec, std::size_t) {
    if (ec) ++not_sent_;
    else ++sent_;
  });
}

void CigiEndpoint::stop() {
  stopped_ = true;
  asio::error_code ignored;
  socket_.close(ignored);
}

}  // namespace cloudsvc
