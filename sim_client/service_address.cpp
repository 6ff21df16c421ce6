// Service address parsing (service_address.h).
#include "sim_client/service_address.h"

#include "common/option_address.h"
#include "sim_client/service_connection.h"

namespace cloudsvc::client {

// The --connect syntax of the command line (common/option_address.h), ports 1..65535.
ServiceAddress parse_service_address(const std::string& address) {
  cli::Endpoint endpoint;
  if (const auto problem = cli::endpoint_problem(address, cli::PortUse::Connect, endpoint))
    throw ConnectionError(address + ": " + *problem);
  ServiceAddress a;
  if (endpoint.kind == cli::Endpoint::Kind::Unix) {
    a.kind = ServiceAddress::Kind::Unix;
    a.path = endpoint.path;
    return a;
  }
  a.kind = ServiceAddress::Kind::Tcp;
  a.host = endpoint.host;
  a.port = endpoint.port;
  return a;
}

}  // namespace cloudsvc::client
