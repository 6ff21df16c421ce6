// Sub-commands of the `sim_client` executable (sim_client_main.cpp). Each add_*_command
// registers its CLI11 sub-command and flags on `app` and returns the function that
// validates the collected flags (throwing cli::FlagError, common/option_values.h, or
// UsageError) and runs the command (throwing RunError, client::ConnectionError or
// FlightLogError), returning the exit code.
// Documented in docs/SIM_CLIENT.md.
#pragma once

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace cloudsvc::sim {

struct Command {
  CLI::App* app = nullptr;  // the CLI11 sub-command
  std::function<int()> run;
};

Command add_replay_command(CLI::App& app);   // cmd_replay.cpp
Command add_sweep_command(CLI::App& app);    // cmd_sweep.cpp
Command add_weather_command(CLI::App& app);  // cmd_weather.cpp
Command add_watch_command(CLI::App& app);    // cmd_watch.cpp
Command add_soak_command(CLI::App& app);     // cmd_soak.cpp
Command add_cigi_command(CLI::App& app);     // cmd_cigi.cpp

// Shared flag text and checks of the commands (cmd_common.cpp).
inline constexpr const char* kDefaultAddress = "tcp://127.0.0.1:7420";
// Help text of --connect.
std::string connect_help();
// --frame-timeout: seconds in (0, 86400]; cli::FlagError otherwise.
double parse_frame_timeout(const std::string& text);
std::string frame_timeout_help();
inline constexpr const char* kDefaultFrameTimeout_s = "120";

// Footer line of every --help.
inline constexpr const char* kExitCodesHelp =
    "Exit codes: 0 success, 1 runtime failure (cannot connect, service error, write failure), 2 bad input (flag or "
    "input file).";

// Prints "sim_client <command>: <text>" on stderr (warnings during a run).
void warn(const std::string& command, const std::string& text);

}  // namespace cloudsvc::sim
