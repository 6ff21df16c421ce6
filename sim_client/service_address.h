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

// Throws ConnectionError (service_connection.h) "<address>: <problem>" when the text is not
// one of the forms of common/option_address.h (the --connect flag's syntax: a numeric
// host or localhost, port 1..65535, a socket path of at most 107 bytes).
ServiceAddress parse_service_address(const std::string& address);

}  // namespace cloudsvc::client
