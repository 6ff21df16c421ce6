// Flags shared by the sim_client sub-commands (commands.h).
#include <cstdio>

#include "common/option_values.h"
#include "sim_client/commands.h"

namespace cloudsvc::sim {

std::string connect_help() {
  return std::string("Service address: tcp://HOST:PORT or unix:PATH (the socket of `cloudsvc serve --listen`); default ") +
         kDefaultAddress;
}

double parse_frame_timeout(const std::string& text) {
  return cli::parse_number("--frame-timeout", text, cli::Range{0.0, 86400.0, true, "seconds"});
}

std::string frame_timeout_help() {
  return std::string("Longest wait for one frame before giving up, seconds, (0, 86400]; default ") + kDefaultFrameTimeout_s;
}

void warn(const std::string& command, const std::string& text) {
  std::fprintf(stderr, "sim_client %s: %s\n", command.c_str(), text.c_str());
  std::fflush(stderr);
}

}  // namespace cloudsvc::sim
