// Flags shared by the sim_client sub-commands (commands.h).
#include <arpa/inet.h>

#include <cstdio>

#include "sim_client/cli_values.h"
#include "sim_client/commands.h"
#include "sim_client/text_input.h"

namespace cloudsvc::sim {

void check_address(const std::string& flag, const std::string& address) {
  const char* expected = "expected tcp://HOST:PORT (HOST a numeric IPv4 address, [IPv6] or localhost; PORT 1..65535) or unix:PATH";
  if (address.rfind("unix:", 0) == 0) {
    if (address.size() == 5) fail_flag(flag, address, expected);
    return;
  }
  if (address.rfind("tcp://", 0) != 0) fail_flag(flag, address, expected);
  const std::string hp = address.substr(6);
  const auto colon = hp.rfind(':');
  if (colon == std::string::npos || colon == 0) fail_flag(flag, address, expected);
  std::string host = hp.substr(0, colon);
  const bool bracketed = host.size() > 2 && host.front() == '[' && host.back() == ']';
  if (bracketed) host = host.substr(1, host.size() - 2);
  unsigned char addr[16];
  const bool ok_host = host == "localhost" || (!bracketed && ::inet_pton(AF_INET, host.c_str(), addr) == 1) ||
                       (bracketed && ::inet_pton(AF_INET6, host.c_str(), addr) == 1);
  if (!ok_host) fail_flag(flag, address, std::string("bad host (names other than localhost are not resolved); ") + expected);
  const std::string port = hp.substr(colon + 1);
  const std::optional<double> p = parse_number(port);
  if (port.empty() || port.find_first_not_of("0123456789") != std::string::npos || !p || *p < 1 || *p > 65535)
    fail_flag(flag, address, std::string("port out of range [1, 65535]; ") + expected);
}

std::string connect_help() {
  return std::string("Service address: tcp://HOST:PORT or unix:PATH (the socket of `cloudsvc serve --listen`); default ") +
         kDefaultAddress;
}

double parse_frame_timeout(const std::string& text) {
  return parse_flag_number("--frame-timeout", text, NumberRange{0.0, 86400.0, true, "seconds"});
}

std::string frame_timeout_help() {
  return std::string("Longest wait for one frame before giving up, seconds, (0, 86400]; default ") + kDefaultFrameTimeout_s;
}

void warn(const std::string& command, const std::string& text) {
  std::fprintf(stderr, "sim_client %s: %s\n", command.c_str(), text.c_str());
  std::fflush(stderr);
}

}  // namespace cloudsvc::sim
