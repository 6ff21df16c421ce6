// `sim_client sweep FILE`: renders a list or grid of poses (sweep_plan.h) as linear EXR
// frames and writes OUT/manifest.csv with per-frame statistics (manifest.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "common/option_address.h"
#include "common/option_paths.h"
#include "common/option_values.h"
#include "protocol/weather_conversion.h"
#include "sim_client/client_session.h"
#include "sim_client/commands.h"
#include "sim_client/image_stats.h"
#include "sim_client/manifest.h"
#include "sim_client/progress.h"
#include "sim_client/run_summary.h"
#include "sim_client/sweep_plan.h"
#include "sim_client/tone_map.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

constexpr const char* kName = "sweep";
constexpr const char* kServiceWeather = "service";  // manifest label before the sweep sets weather

struct SweepArgs {
  std::string file, connect = kDefaultAddress, out, size = "640x360", fov = "60", frame_timeout = kDefaultFrameTimeout_s;
  bool png = false;
};

struct SweepOptions {
  std::string file, address;
  std::filesystem::path out_dir;  // absolute
  std::uint32_t width = 640, height = 360;
  double fov_deg = 60.0;
  std::chrono::milliseconds frame_timeout{120000};
  bool png = false;
};

SweepOptions validate(const SweepArgs& a) {
  SweepOptions o;
  o.file = a.file;
  cli::parse_endpoint("--connect", a.connect, cli::PortUse::Connect);
  o.address = a.connect;
  if (a.out.empty()) cli::fail("--out", a.out, "required: the directory for the frames and manifest.csv");
  cli::check_output_directory("--out", a.out);  // created when the run starts
  std::error_code ec;
  o.out_dir = std::filesystem::absolute(a.out, ec);
  std::tie(o.width, o.height) = cli::parse_image_size("--size", a.size);
  o.fov_deg = cli::parse_number("--fov", a.fov, cli::kFieldOfView);
  o.frame_timeout = std::chrono::milliseconds(static_cast<long long>(parse_frame_timeout(a.frame_timeout) * 1000.0));
  o.png = a.png;
  return o;
}

int run_sweep(const SweepOptions& o, const SweepPlan& plan) {
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) throw RunError("--out " + o.out_dir.string() + ": cannot create: " + ec.message());
  const std::filesystem::path manifest_path = o.out_dir / "manifest.csv";
  std::ofstream manifest(manifest_path);
  if (!manifest) throw RunError(manifest_path.string() + ": cannot write");
  manifest << manifest_header() << '\n';

  ClientSession session(o.address, "sim_client sweep");
  protocol::SetView view;
  view.width = o.width;
  view.height = o.height;
  view.hfov_deg = o.fov_deg;
  view.sinks = protocol::sink::kFile;  // EXR only: linear radiance for physical statistics
  view.file_dir = std::filesystem::absolute(o.out_dir).string();  // the service's cwd is not ours
  view.file_format = protocol::FileFormat::Exr;
  session.set_view(view, [](const std::string& w) { warn(kName, w); });

  ProgressReporter progress(std::cerr, ProgressReporter::stderr_is_terminal(), plan.entries.size(), "sweep");
  const auto start = Clock::now();
  std::optional<std::size_t> weather_sent;  // index into plan.weathers
  std::size_t rows = 0, refused = 0, nonfinite_frames = 0;
  std::vector<double> latency_ms;  // FrameReady.latency_ms per rendered entry, ms
  for (std::size_t i = 0; i < plan.entries.size(); ++i) {
    const SweepEntry& e = plan.entries[i];
    if (e.weather && e.weather != weather_sent) {
      const std::uint64_t seq = session.send(to_message(plan.weathers[*e.weather].weather));
      for (const protocol::Error& err : session.sync(std::chrono::milliseconds(10000)))
        if (err.answers_seq == seq)
          throw RunError(e.origin + ": the service rejected weather '" + plan.weathers[*e.weather].label +
                         "': " + describe_error(err));
        else warn(kName, "service: " + describe_error(err));
      weather_sent = e.weather;
    }
    protocol::Pose pose;
    pose.sim_time_s = e.utc_unix_s;  // the sweep's clock is UTC
    pose.utc_unix_s = e.utc_unix_s;
    pose.lat_deg = e.lat_deg;
    pose.lon_deg = e.lon_deg;
    pose.alt_m = e.alt_m;
    pose.heading_deg = e.heading_deg;
    pose.pitch_deg = e.pitch_deg;
    pose.roll_deg = e.roll_deg;
    pose.flags = protocol::pose_flag::kTeleport;  // every entry is its own view: no history
    const std::uint64_t seq = session.send(pose);
    const auto frame = session.wait_frame(pose, seq, o.frame_timeout,
                                          [](const protocol::Error& err) { warn(kName, "service: " + describe_error(err)); });
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (!frame) {
      ++refused;
      warn(kName, e.origin + ": no frame (the service refused the pose)");
      progress.update(i + 1, elapsed);
      continue;
    }
    if (!frame->file_path) throw RunError(e.origin + ": the service wrote no file for frame " + std::to_string(frame->frame_number));
    ManifestRow row;
    row.frame = frame->frame_number;
    row.lat_deg = e.lat_deg;
    row.lon_deg = e.lon_deg;
    row.alt_m = e.alt_m;
    row.heading_deg = e.heading_deg;
    row.pitch_deg = e.pitch_deg;
    row.roll_deg = e.roll_deg;
    row.utc_unix_s = e.utc_unix_s;
    row.weather = weather_sent ? plan.weathers[*weather_sent].label : kServiceWeather;
    row.render_ms = frame->render_ms;
    row.latency_ms = frame->latency_ms;
    latency_ms.push_back(frame->latency_ms);
    row.file = *frame->file_path;
    try {
      row.stats = read_image_stats(row.file);
      if (o.png) write_display_png(std::filesystem::path(row.file).replace_extension(".png").string(), read_display_image(row.file));
    } catch (const std::exception& ex) {
      throw RunError(std::string(ex.what()) + " (the frame must be readable here: run the sweep on the service's machine)");
    }
    if (row.stats.nonfinite > 0) ++nonfinite_frames;
    manifest << manifest_line(row) << '\n' << std::flush;
    ++rows;
    progress.update(i + 1, elapsed);
  }
  const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  progress.finish(plan.entries.size(), wall_s);
  if (!manifest) throw RunError(manifest_path.string() + ": write failed");
  SweepSummary summary;
  summary.rows = rows;
  summary.entries = plan.entries.size();
  summary.refused = refused;
  summary.nonfinite_frames = nonfinite_frames;
  summary.wall_s = wall_s;
  summary.latency_ms = std::move(latency_ms);
  summary.manifest = manifest_path.string();
  std::printf("%s\n", format_sweep_summary(summary).c_str());
  std::fflush(stdout);
  return rows == plan.entries.size() ? cli::kExitOk : cli::kExitFailure;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Render a list or grid of poses (JSON or CSV, docs/SIM_CLIENT.md) as linear EXR frames and write "
             "manifest.csv with mean radiance, cloud fraction and NaN/Inf counts per frame");
  cmd->add_option("file", args->file, "Sweep file: .json (poses or grid) or .csv")->required()->type_name("FILE");
  cmd->add_option("--connect", args->connect, connect_help())->type_name("ADDR");
  cmd->add_option("--out", args->out,
                  "Directory for the EXR frames and manifest.csv (required); created if absent; must be on the "
                  "service's machine (the service writes the frames, sim_client reads them)")
      ->type_name("DIR");
  cmd->add_option("--size", args->size, "Image size in pixels, WxH, each side in [1, 8192]; default 640x360")->type_name("WxH");
  cmd->add_option("--fov", args->fov, "Horizontal field of view, degrees, (0, 170]; default 60")->type_name("DEG");
  cmd->add_flag("--png", args->png, "Also write a tone-mapped 8-bit sRGB PNG next to each EXR frame, for people");
  cmd->add_option("--frame-timeout", args->frame_timeout, frame_timeout_help())->type_name("S");
  cmd->footer(std::string(kExitCodesHelp) +
              "\nExample: sim_client sweep sweep.json --connect unix:/tmp/cloudsvc.sock --out sweep/ --size 320x180");
  return {cmd, [args]() -> int {
            const SweepOptions o = validate(*args);
            const SweepPlan plan = load_sweep(o.file);
            return run_sweep(o, plan);
          }};
}

}  // namespace cloudsvc::sim
