// Service addresses on the command line (option_address.h).
#include "common/option_address.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/un.h>

#include "common/option_values.h"

namespace cloudsvc::cli {

namespace {

static_assert(kMaxUnixPathBytes == sizeof(sockaddr_un{}.sun_path) - 1);

constexpr std::string_view kTcpScheme = "tcp://";
constexpr std::string_view kUnixScheme = "unix:";
constexpr std::string_view kUdpScheme = "udp:";
constexpr int kMaxPort = 65535;

int min_port(PortUse use) { return use == PortUse::Listen ? 0 : 1; }

// "[0, 65535]" or "[1, 65535]".
std::string port_range(PortUse use) {
  std::string text = "[";  // appended piecewise: GCC 12 warns (-Wrestrict) on a + chain here
  text += std::to_string(min_port(use));
  text += ", ";
  text += std::to_string(kMaxPort);
  text += "]";
  return text;
}

std::string forms(PortUse use) {
  return "expected tcp://HOST:PORT (HOST a numeric IPv4 address, [IPv6 address] or localhost; PORT in " +
         port_range(use) + (use == PortUse::Listen ? ", 0 = any free port" : "") + ") or unix:PATH";
}

// PORT of tcp://HOST:PORT: decimal digits only, within the range of `use`.
std::optional<std::string> port_problem(std::string_view port, PortUse use, std::uint16_t& out) {
  if (port.empty()) return "missing port after ':' (integer in " + port_range(use) + ")";
  const std::optional<int> value = parse_digits(port);
  if (!value) return "port " + std::string(port) + " is not an integer in " + port_range(use);
  if (*value < min_port(use) || *value > kMaxPort) {
    return "port " + std::string(port) + " out of range " + port_range(use);
  }
  out = static_cast<std::uint16_t>(*value);
  return std::nullopt;
}

// Canonical text of a numeric address of `family` (AF_INET/AF_INET6), or "" if `host`
// is not one. No name is resolved.
std::string canonical_address(int family, const std::string& host) {
  unsigned char binary[sizeof(in6_addr)];
  if (inet_pton(family, host.c_str(), binary) != 1) return "";
  char text[INET6_ADDRSTRLEN];
  return inet_ntop(family, binary, text, sizeof text) != nullptr ? text : "";
}

// tcp://HOST:PORT; `rest` is the text after "tcp://".
std::optional<std::string> tcp_problem(std::string_view rest, PortUse use, Endpoint& out) {
  out.kind = Endpoint::Kind::Tcp;
  std::string host;
  std::size_t colon = std::string_view::npos;
  bool bracketed = false;
  if (!rest.empty() && rest.front() == '[') {
    const std::size_t close = rest.find(']');
    if (close == std::string_view::npos) return "missing ']' after the IPv6 address";
    host = std::string(rest.substr(1, close - 1));
    bracketed = true;
    if (close + 1 == rest.size() || rest[close + 1] != ':') {
      return "missing :PORT after the address (integer in " + port_range(use) + ")";
    }
    colon = close + 1;
  } else {
    colon = rest.rfind(':');
    if (colon == std::string_view::npos) return "missing :PORT after the host (integer in " + port_range(use) + ")";
    host = std::string(rest.substr(0, colon));
    if (host.find(':') != std::string::npos) return "an IPv6 address must be in brackets, e.g. tcp://[::1]:7420";
  }
  if (auto problem = port_problem(rest.substr(colon + 1), use, out.port)) return problem;
  if (host.empty()) return "missing host; " + forms(use);
  if (!bracketed && host == "localhost") {
    out.host = "127.0.0.1";
    return std::nullopt;
  }
  out.host = canonical_address(bracketed ? AF_INET6 : AF_INET, host);
  if (out.host.empty()) {
    return bracketed ? "\"" + host + "\" is not a numeric IPv6 address"
                     : "host \"" + host +
                           "\" is not a numeric IPv4 address or localhost (host names are not resolved; IPv6 "
                           "goes in brackets)";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> endpoint_problem(std::string_view text, PortUse use, Endpoint& out) {
  out = Endpoint{};
  if (text.starts_with(kTcpScheme)) return tcp_problem(text.substr(kTcpScheme.size()), use, out);
  if (!text.starts_with(kUnixScheme)) return forms(use);
  out.kind = Endpoint::Kind::Unix;
  out.path = std::string(text.substr(kUnixScheme.size()));
  if (out.path.empty()) return "empty socket path; expected unix:PATH";
  if (out.path.size() > kMaxUnixPathBytes) {
    return "socket path is " + std::to_string(out.path.size()) + " bytes, at most " +
           std::to_string(kMaxUnixPathBytes) + " (sun_path)";
  }
  return std::nullopt;
}

Endpoint parse_endpoint(std::string_view flag, const std::string& text, PortUse use) {
  Endpoint endpoint;
  if (auto problem = endpoint_problem(text, use, endpoint)) fail(flag, text, *problem);
  return endpoint;
}

std::string UdpEndpoint::text() const {
  const bool v6 = host.find(':') != std::string::npos;
  std::string t(kUdpScheme);  // appended piecewise: GCC 12 warns (-Wrestrict) on a + chain here
  if (v6) t += '[';
  t += host;
  if (v6) t += ']';
  t += ':';
  t += std::to_string(port);
  return t;
}

std::optional<std::string> udp_endpoint_problem(std::string_view text, PortUse use, UdpEndpoint& out) {
  out = UdpEndpoint{};
  const std::string expected = "expected udp:HOST:PORT (HOST a numeric IPv4 address, [IPv6 address] or localhost) or "
                               "udp:PORT (loopback), PORT in " + port_range(use) +
                               (use == PortUse::Listen ? ", 0 = any free port" : "");
  if (!text.starts_with(kUdpScheme)) return expected;
  const std::string_view rest = text.substr(kUdpScheme.size());
  if (rest.find(':') == std::string_view::npos) {  // udp:PORT
    if (auto problem = port_problem(rest, use, out.port)) return *problem + "; " + expected;
    return std::nullopt;
  }
  Endpoint tcp;
  if (auto problem = tcp_problem(rest, use, tcp)) {
    if (problem->find("tcp://") != std::string::npos) return expected;  // the tcp forms' text does not apply
    return problem;
  }
  out.host = tcp.host;
  out.port = tcp.port;
  return std::nullopt;
}

UdpEndpoint parse_udp_endpoint(std::string_view flag, const std::string& text, PortUse use) {
  UdpEndpoint endpoint;
  if (auto problem = udp_endpoint_problem(text, use, endpoint)) fail(flag, text, *problem);
  return endpoint;
}

}  // namespace cloudsvc::cli
