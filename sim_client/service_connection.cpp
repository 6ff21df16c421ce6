#include "sim_client/service_connection.h"

#include <asio.hpp>

#include <deque>
#include <variant>

#include "protocol/codec.h"
#include "protocol/framing.h"
#include "protocol/handshake.h"
#include "sim_client/connection_failure.h"
#include "sim_client/service_address.h"

namespace cloudsvc::client {

namespace {
using Tcp = asio::ip::tcp;
using Local = asio::local::stream_protocol;
}  // namespace

struct ServiceConnection::Impl {
  asio::io_context io;
  std::variant<Tcp::socket, Local::socket> socket{Tcp::socket(io)};
  protocol::FrameDecoder decoder;
  std::deque<protocol::Message> ready;
  protocol::Welcome welcome;
  std::uint64_t next_seq = 1;
  std::array<std::uint8_t, 65536> buffer{};

  void connect(const std::string& address, std::chrono::milliseconds timeout) {
    asio::error_code ec;
    const ServiceAddress a = parse_service_address(address);
    if (a.kind == ServiceAddress::Kind::Tcp) {
      const auto addr = asio::ip::make_address(a.host, ec);
      if (ec) throw ConnectionError(address + ": bad host: " + ec.message());
      Tcp::socket s(io);
      s.async_connect(Tcp::endpoint(addr, a.port), [&](const asio::error_code& e) { ec = e; });
      io.restart();
      io.run_for(timeout);
      if (!io.stopped()) throw ConnectionError(address + ": connect timed out");
      if (ec) throw ConnectionError(address + ": " + ec.message());
      s.set_option(Tcp::no_delay(true));
      socket = std::move(s);
    } else {
      Local::socket s(io);
      s.connect(Local::endpoint(a.path), ec);
      if (ec) throw ConnectionError(address + ": " + ec.message());
      socket = std::move(s);
    }
  }

  void write(const std::vector<std::uint8_t>& bytes) {
    asio::error_code ec;
    std::visit([&](auto& s) { asio::write(s, asio::buffer(bytes), ec); }, socket);
    if (ec) throw ConnectionError(connection_failure_text("send", ec));
  }

  // Reads once (with timeout) and decodes whatever completed. False on timeout.
  bool pump(std::chrono::milliseconds timeout) {
    asio::error_code ec;
    std::size_t n = 0;
    bool done = false;
    std::visit([&](auto& s) {
      s.async_read_some(asio::buffer(buffer), [&](const asio::error_code& e, std::size_t k) {
        ec = e;
        n = k;
        done = true;
      });
    }, socket);
    io.restart();
    io.run_for(timeout);
    if (!done) {
      std::visit([](auto& s) { asio::error_code ignore; s.cancel(ignore); }, socket);
      io.restart();
      io.run();  // let the cancelled read finish
      if (!done || ec == asio::error::operation_aborted) return false;
    }
    if (ec) throw ConnectionError(connection_failure_text("receive", ec));
    decoder.feed(std::span<const std::uint8_t>(buffer.data(), n));
    while (auto payload = decoder.next()) {
      protocol::DecodeResult r = protocol::decode(*payload);
      if (!r.ok()) throw ConnectionError("undecodable message from the service: " + r.error_text);
      ready.push_back(std::move(*r.message));
    }
    if (decoder.failed()) throw ConnectionError("framing error from the service: " + decoder.error_text());
    return true;
  }
};

ServiceConnection::ServiceConnection(const std::string& address, const std::string& client_name,
                                     std::chrono::milliseconds timeout, std::uint32_t capabilities)
    : impl_(std::make_unique<Impl>()) {
  impl_->connect(address, timeout);
  protocol::Hello hello;
  hello.client_name = client_name;
  hello.capabilities = capabilities;
  send(hello);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (impl_->ready.empty()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || !impl_->pump(left)) throw ConnectionError(address + ": no Welcome from the service");
  }
  protocol::Message first = std::move(impl_->ready.front());
  impl_->ready.pop_front();
  if (auto* e = std::get_if<protocol::Error>(&first))
    throw ConnectionError(address + ": refused: " + std::string(protocol::error_code_name(e->code)) + ": " + e->text);
  auto* w = std::get_if<protocol::Welcome>(&first);
  if (!w) throw ConnectionError(address + ": first message was not Welcome");
  if (w->major != protocol::kProtocolMajor)
    throw ConnectionError(address + ": protocol major " + std::to_string(w->major) + ", this client speaks " +
                          std::to_string(protocol::kProtocolMajor));
  impl_->welcome = *w;
}

ServiceConnection::~ServiceConnection() {
  std::visit([](auto& s) { asio::error_code ec; s.close(ec); }, impl_->socket);
}

const protocol::Welcome& ServiceConnection::welcome() const { return impl_->welcome; }

std::uint64_t ServiceConnection::send(const protocol::Message& m) {
  const std::uint64_t seq = impl_->next_seq++;
  impl_->write(protocol::frame(protocol::encode(m, seq)));
  return seq;
}

void ServiceConnection::send_raw(const std::uint8_t* data, std::size_t n) {
  impl_->write(std::vector<std::uint8_t>(data, data + n));
}

std::optional<protocol::Message> ServiceConnection::receive(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (impl_->ready.empty()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || !impl_->pump(left)) return std::nullopt;
  }
  protocol::Message m = std::move(impl_->ready.front());
  impl_->ready.pop_front();
  return m;
}

}  // namespace cloudsvc::client
