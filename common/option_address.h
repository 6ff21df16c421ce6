// Flag values that name a service address: "tcp://HOST:PORT" (HOST a numeric IPv4 address,
// an IPv6 address in brackets such as [::1], or localhost; no host name is resolved) or
// "unix:PATH" (a Unix stream socket). Used by `cloudsvc serve --listen` and by sim_client
// --connect (and its connections, sim_client/service_address.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cloudsvc::cli {

// Longest Unix socket path: sockaddr_un.sun_path holds 108 bytes including the NUL.
inline constexpr std::size_t kMaxUnixPathBytes = 107;

// Which ports an address may name.
enum class PortUse {
  Listen,   // [0, 65535]; 0 = the kernel picks a free port
  Connect,  // [1, 65535]
};

struct Endpoint {
  enum class Kind { Tcp, Unix } kind = Kind::Tcp;
  std::string host;        // Tcp: canonical numeric address (inet_ntop), localhost = 127.0.0.1
  std::uint16_t port = 0;  // Tcp
  std::string path;        // Unix: socket path, 1..kMaxUnixPathBytes bytes
};

// The problem with `text` as an address, naming the part that is wrong ("port 65536 out of
// range [0, 65535]"), or nullopt with `out` filled. A Unix path is only checked for its
// length here; whether it can be bound or connected to is for the caller.
std::optional<std::string> endpoint_problem(std::string_view text, PortUse use, Endpoint& out);

// The address of `flag`, or FlagError "<flag> <text>: <problem>" (option_values.h).
Endpoint parse_endpoint(std::string_view flag, const std::string& text, PortUse use);

// A UDP address (CIGI): "udp:HOST:PORT" with HOST as for tcp:// (numeric IPv4, [IPv6] or
// localhost), or "udp:PORT" for the loopback address 127.0.0.1.
struct UdpEndpoint {
  std::string host = "127.0.0.1";  // canonical numeric address
  std::uint16_t port = 0;
  std::string text() const;        // udp:HOST:PORT, IPv6 in brackets
};

// The problem with `text` as a UDP address, or nullopt with `out` filled.
std::optional<std::string> udp_endpoint_problem(std::string_view text, PortUse use, UdpEndpoint& out);
// The UDP address of `flag`, or FlagError "<flag> <text>: <problem>".
UdpEndpoint parse_udp_endpoint(std::string_view flag, const std::string& text, PortUse use);

}  // namespace cloudsvc::cli
