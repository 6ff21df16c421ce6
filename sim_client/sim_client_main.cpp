// sim_client: drives a running `cloudsvc serve` like a flight simulator would (replay,
// sweep, weather), watches its shared-memory frames (watch) and load-tests it (soak).
// docs/SIM_CLIENT.md.
// Exit codes: 0 success (and --help), 1 runtime failure (connection, service error,
// write failure), 2 bad input (flag, input file); every failure is one line on stderr.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "common/option_values.h"
#include "sim_client/commands.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/service_connection.h"
#include "sim_client/usage_errors.h"

namespace cli = cloudsvc::cli;

namespace {

// One line: line breaks from any source become spaces.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

int fail(const std::string& prefix, const std::string& message, int code) {
  std::fprintf(stderr, "%s%s\n", prefix.c_str(), one_line(message).c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cloudsvc::sim;
  CLI::App app("sim_client: a simulator-side client of the cloudsvc service (docs/SIM_CLIENT.md)", "sim_client");
  app.require_subcommand(1);
  std::vector<Command> commands = {add_replay_command(app), add_sweep_command(app), add_weather_command(app),
                                   add_watch_command(app), add_soak_command(app),
                                   add_cigi_command(app)};
  app.footer(std::string(kExitCodesHelp) +
             "\nExample: sim_client replay sim_client/demo_flight.csv --connect unix:/tmp/cloudsvc.sock "
             "--out frames/ --size 320x180");
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for (const Command& c : commands) known = known || c.app->get_name() == argv[1];
    if (!known)
      return fail("sim_client: ", std::string(argv[1]) + ": unknown sub-command (expected replay, sweep, weather, watch or soak)",
                  cli::kExitBadInput);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string where = "sim_client: ";
    for (const Command& c : commands)
      if (c.app->parsed()) where = "sim_client " + c.app->get_name() + ": ";
    std::string text = e.what();
    if (text == "A subcommand is required") text += " (replay, sweep, weather, watch or soak; see sim_client --help)";
    return fail(where, text, cli::kExitBadInput);
  }
  for (const Command& c : commands) {
    if (!c.app->parsed()) continue;
    const std::string prefix = "sim_client " + c.app->get_name() + ": ";
    try {
      return c.run();
    } catch (const cloudsvc::sim::FlightLogError& e) {
      return fail("", e.what(), cli::kExitBadInput);  // "<file>:<line>: <problem>"
    } catch (const cli::FlagError& e) {  // a bad flag value: "<flag> <value>: <reason>"
      return fail(prefix, e.what(), cli::kExitBadInput);
    } catch (const UsageError& e) {
      return fail(prefix, e.what(), cli::kExitBadInput);
    } catch (const cloudsvc::client::ConnectionError& e) {
      return fail(prefix, e.what(), cli::kExitFailure);
    } catch (const std::exception& e) {
      return fail(prefix, e.what(), cli::kExitFailure);
    }
  }
  return cli::kExitBadInput;
}
