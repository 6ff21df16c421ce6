// Service address parsing (service_address.h).
#include "sim_client/service_address.h"

#include "sim_client/service_connection.h"

namespace cloudsvc::client {

ServiceAddress parse_service_address(const std::string& address) {
  ServiceAddress a;
  if (address.rfind("unix:", 0) == 0 && address.size() > 5) {
    a.kind = ServiceAddress::Kind::Unix;
    a.path = address.substr(5);
    return a;
  }
  if (address.rfind("tcp://", 0) != 0) throw ConnectionError(address + ": expected tcp://HOST:PORT or unix:PATH");
  const std::string hp = address.substr(6);
  const auto colon = hp.rfind(':');
  if (colon == std::string::npos) throw ConnectionError(address + ": expected tcp://HOST:PORT");
  std::string host = hp.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') host = host.substr(1, host.size() - 2);
  if (host == "localhost") host = "127.0.0.1";
  int port = 0;
  try {
    port = std::stoi(hp.substr(colon + 1));
  } catch (...) {
    port = 0;
  }
  if (port < 1 || port > 65535) throw ConnectionError(address + ": bad port");
  a.kind = ServiceAddress::Kind::Tcp;
  a.host = host;
  a.port = static_cast<std::uint16_t>(port);
  return a;
}

}  // namespace cloudsvc::client
