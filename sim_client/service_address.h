// A service address as the sim_client commands write it: "tcp://HOST:PORT" (HOST a numeric
// IPv4 address, an IPv6 address in brackets, or localhost) or "unix:PATH". Parsed once
// here for every connection the client makes (ServiceConnection, the soak clients).
#pragma once

#include <cstdint>
#include <string>

namespace cloudsvc::client {

struct ServiceAddress {
  enum class Kind { Tcp, Unix } kind = Kind::Tcp;
  std::string host;        // Tcp: numeric address, brackets removed, localhost = 127.0.0.1
  std::uint16_t port = 0;  // Tcp: 1..65535
  std::string path;        // Unix: socket file path
};

// Throws ConnectionError (service_connection.h) "<address>: expected tcp://HOST:PORT or
// unix:PATH" (or naming the bad port) when the text has neither form. The host is only
// split off here; asio checks that it is a numeric address when connecting.
ServiceAddress parse_service_address(const std::string& address);

}  // namespace cloudsvc::client
