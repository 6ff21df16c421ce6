// `sim_client soak`: a load and endurance test of a running service. N clients, each its
// own connection, send poses along a moving track at a fixed rate for a duration and read
// every reply; the run reports poses, frames, frame rate, latency, errors, disconnects and
// the service's memory (soak_run.h, soak_summary.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <memory>

#include "common/option_address.h"
#include "common/option_paths.h"
#include "common/option_values.h"
#include "sim_client/commands.h"
#include "sim_client/process_rss.h"
#include "sim_client/soak_run.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

constexpr const char* kName = "soak";
constexpr double kMaxDuration_s = 7.0 * 86400.0;  // a week: longer runs are several runs
constexpr long long kMaxClients = 1024;           // the protocol's most clients (serve --max-clients)
constexpr double kMaxRate_hz = 10000.0;           // per client; 0.1 ms between poses
constexpr long long kMaxPid = 4194304;            // Linux pid_max limit (2^22)

// Raw flag text, as CLI11 collects it.
struct SoakArgs {
  std::vector<std::string> connect;
  std::string clients = "4", rate = "60", duration = "60", size = "640x360", service_pid, render_every, json;
  bool expect_errors = false;
};

struct SoakCommandOptions {
  SoakOptions run;
  std::string json;  // report file; empty = none
  bool expect_errors = false;
};

SoakCommandOptions validate(const SoakArgs& a) {
  SoakCommandOptions o;
  o.run.addresses = a.connect.empty() ? std::vector<std::string>{kDefaultAddress} : a.connect;
  for (const std::string& address : o.run.addresses) cli::parse_endpoint("--connect", address, cli::PortUse::Connect);
  o.run.clients = static_cast<std::size_t>(cli::parse_integer("--clients", a.clients, 1, kMaxClients, "connections"));
  o.run.rate_hz = cli::parse_number("--rate", a.rate, cli::Range{0.0, kMaxRate_hz, true, "poses per second per client"});
  o.run.duration_s = cli::parse_duration("--duration", a.duration, kMaxDuration_s);
  std::tie(o.run.width, o.run.height) = cli::parse_image_size("--size", a.size);
  if (!a.render_every.empty())
    o.run.render_every = static_cast<std::uint64_t>(cli::parse_integer("--render-every", a.render_every, 1, 1000000, "poses"));
  if (!a.service_pid.empty()) {
    o.run.service_pid = static_cast<int>(cli::parse_integer("--service-pid", a.service_pid, 1, kMaxPid, "process id"));
    if (!process_rss_bytes(o.run.service_pid))
      cli::fail("--service-pid", a.service_pid, "no such process, or no VmRSS in /proc/" + a.service_pid + "/status");
  }
  if (!a.json.empty()) {
    cli::check_writable_file("--json", a.json);
    o.json = a.json;
  }
  o.expect_errors = a.expect_errors;
  return o;
}

int run_soak_command(const SoakCommandOptions& o) {
  const SoakSummary summary = run_soak(o.run, [](const std::string& line) {
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
  });
  std::printf("%s", format_soak_report(summary, o.expect_errors).c_str());
  std::fflush(stdout);
  if (!o.json.empty()) {
    std::ofstream f(o.json);
    f << soak_report(summary, o.expect_errors).dump(2) << "\n";
    if (!f) throw RunError("--json " + o.json + ": cannot write");
  }
  const std::vector<std::string> failures = soak_failures(summary, o.expect_errors);
  if (failures.empty()) return cli::kExitOk;
  std::string why;
  for (const std::string& f : failures) why += (why.empty() ? "" : "; ") + f;
  throw RunError("failed: " + why);
}

}  // namespace

Command add_soak_command(CLI::App& app) {
  auto args = std::make_shared<SoakArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Load and endurance test: N clients, each its own connection, stream poses along a moving track at a "
             "fixed rate for a duration and read every reply; report poses, frames, frame rate, FrameReady latency, "
             "errors, disconnects and the service's memory (docs/SIM_CLIENT.md)");
  cmd->add_option("--connect", args->connect,
                  connect_help() + "; repeat it to spread the clients over several addresses (round-robin)")
      ->type_name("ADDR");
  cmd->add_option("--clients", args->clients, "Client connections, integer in [1, 1024]; default 4")->type_name("N");
  cmd->add_option("--rate", args->rate, "Poses per second per client, (0, 10000]; default 60")->type_name("HZ");
  cmd->add_option("--duration", args->duration,
                  "How long to send poses: seconds (90, 90s), minutes (10m) or hours (1.5h), at most a week; default 60")
      ->type_name("D");
  cmd->add_option("--size", args->size,
                  "Image size of the SetView, WxH pixels, each side in [1, 8192]; default 640x360 (sent only when the "
                  "service offers shared memory, else the service renders its own view)")
      ->type_name("WxH");
  cmd->add_option("--service-pid", args->service_pid,
                  "Process id of the service, on this machine: its VmRSS (/proc/PID/status) is sampled once a second "
                  "and reported at the start, the maximum and the end")
      ->type_name("PID");
  cmd->add_option("--render-every", args->render_every,
                  "Also send a RenderRequest after every K-th pose of each client, integer in [1, 1000000]; default none")
      ->type_name("K");
  cmd->add_option("--json", args->json, "Also write the report as JSON to this file")->type_name("FILE");
  cmd->add_flag("--expect-errors", args->expect_errors,
                "Errors from the service do not fail the run (they are still counted); disconnects still do");
  cmd->footer(std::string(kExitCodesHelp) +
              " A soak fails (exit 1) when a client is disconnected, a final StatsRequest goes unanswered, the service "
              "process goes away, no frame arrives, or (without --expect-errors) an Error arrives.\n"
              "Example: sim_client soak --connect unix:/tmp/cloudsvc.sock --clients 8 --rate 1000 --duration 10m "
              "--size 160x90 --service-pid 12345 --json soak.json");
  return {cmd, [args]() -> int { return run_soak_command(validate(*args)); }};
}

}  // namespace cloudsvc::sim
