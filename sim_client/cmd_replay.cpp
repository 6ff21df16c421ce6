// `sim_client replay LOG`: replays a flight log (IGC, ACMI, CSV) through the service, one
// frame per pose (default) or paced by the log's timestamps (--realtime).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "common/option_address.h"
#include "common/option_paths.h"
#include "common/option_values.h"
#include "sim_client/client_session.h"
#include "sim_client/commands.h"
#include "sim_client/contact_sheet.h"
#include "sim_client/flight_log.h"
#include "sim_client/pacing.h"
#include "sim_client/progress.h"
#include "sim_client/replay_poses.h"
#include "sim_client/run_summary.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

constexpr const char* kName = "replay";

// Raw flag text, as CLI11 collects it.
struct ReplayArgs {
  std::string log, connect = kDefaultAddress, out, size = "640x360", fov = "60", fps = "10", max_frames,
                   format = "png", contact_sheet, object, frame_timeout = kDefaultFrameTimeout_s;
  bool realtime = false, skip_out_of_order = false;
};

// Validated options.
struct ReplayOptions {
  std::string log, address;
  std::filesystem::path out_dir;  // absolute; empty = no file sink
  std::uint32_t width = 640, height = 360;
  double fov_deg = 60.0, fps = 10.0;
  std::size_t max_frames = 0;  // 0 = all
  protocol::FileFormat format = protocol::FileFormat::Png;
  std::string contact_sheet;
  LogOptions log_options;
  std::chrono::milliseconds frame_timeout{120000};
  bool realtime = false;
};

ReplayOptions validate(const ReplayArgs& a) {
  ReplayOptions o;
  o.log = a.log;
  cli::parse_endpoint("--connect", a.connect, cli::PortUse::Connect);
  o.address = a.connect;
  std::tie(o.width, o.height) = cli::parse_image_size("--size", a.size);
  o.fov_deg = cli::parse_number("--fov", a.fov, cli::kFieldOfView);
  o.fps = cli::parse_number("--fps", a.fps, cli::Range{0.0, 1000.0, true, "frames per second of log time"});
  if (!a.max_frames.empty())
    o.max_frames = static_cast<std::size_t>(cli::parse_integer("--max-frames", a.max_frames, 1, 50000000, "frames"));
  if (a.format == "png") o.format = protocol::FileFormat::Png;
  else if (a.format == "exr") o.format = protocol::FileFormat::Exr;
  else cli::fail("--format", a.format, "expected png (8-bit sRGB) or exr (linear 32-bit float)");
  if (!a.out.empty()) {
    cli::check_output_directory("--out", a.out);  // created when the run starts
    std::error_code ec;
    o.out_dir = std::filesystem::absolute(a.out, ec);
  }
  if (!a.contact_sheet.empty()) {
    const std::string& c = a.contact_sheet;
    if (!cli::ends_with_ci(c, ".png")) cli::fail("--contact-sheet", c, "expected a file name ending in .png");
    if (a.out.empty()) cli::fail("--contact-sheet", c, "needs --out (the sheet is made from the frame files)");
    cli::check_writable_file("--contact-sheet", c);
    o.contact_sheet = c;
  }
  o.log_options.acmi_object = a.object;
  o.log_options.skip_out_of_order = a.skip_out_of_order;
  o.frame_timeout = std::chrono::milliseconds(static_cast<long long>(parse_frame_timeout(a.frame_timeout) * 1000.0));
  o.realtime = a.realtime;
  return o;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

class Replay {
 public:
  Replay(const ReplayOptions& o, std::vector<protocol::Pose> poses) : o_(o), poses_(std::move(poses)) {
    for (std::size_t i = 0; i < poses_.size(); ++i) index_by_time_[poses_[i].sim_time_s] = i;
  }

  int run() {
    ClientSession session(o_.address, "sim_client replay");
    protocol::SetView view;
    view.width = o_.width;
    view.height = o_.height;
    view.hfov_deg = o_.fov_deg;
    view.sinks = 0;
    if (!o_.out_dir.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(o_.out_dir, ec);
      if (ec) throw RunError("--out " + o_.out_dir.string() + ": cannot create: " + ec.message());
      view.sinks |= protocol::sink::kFile;
      view.file_dir = std::filesystem::absolute(o_.out_dir).string();  // the service's cwd is not ours
      view.file_format = o_.format;
    }
    if (session.offers(protocol::capability::kSinkShm)) view.sinks |= protocol::sink::kShm;
    if (view.sinks == 0)
      throw RunError("the service offers no shared-memory ring (started without --shm): give --out DIR for frame files");
    session.set_view(view, [](const std::string& w) { warn(kName, w); });

    ProgressReporter progress(std::cerr, ProgressReporter::stderr_is_terminal(), poses_.size(), "replay",
                              o_.realtime ? "poses" : "frames");
    const auto start = Clock::now();
    if (o_.realtime) run_realtime(session, progress, start);
    else run_lockstep(session, progress, start);
    summary_.wall_s = seconds_since(start);
    summary_.realtime = o_.realtime;
    progress.finish(summary_.poses_sent, summary_.wall_s);
    std::printf("%s\n", format_replay_summary(summary_).c_str());
    std::fflush(stdout);
    if (!o_.contact_sheet.empty()) write_sheet();
    return summary_.frames > 0 ? cli::kExitOk : cli::kExitFailure;
  }

 private:
  void on_error(const protocol::Error& e) { warn(kName, "service: " + describe_error(e)); }

  void record(const protocol::FrameReady& f) {
    ++summary_.frames;
    summary_.latency_ms.push_back(f.latency_ms);
    summary_.render_ms.push_back(f.render_ms);
    if (f.file_path) files_.push_back({*f.file_path, f.frame_number});
  }

  // One pose at a time: send, wait for its frame.
  void run_lockstep(ClientSession& session, ProgressReporter& progress, Clock::time_point start) {
    for (std::size_t i = 0; i < poses_.size(); ++i) {
      const std::uint64_t seq = session.send(poses_[i]);
      ++summary_.poses_sent;
      const auto frame = session.wait_frame(poses_[i], seq, o_.frame_timeout, [&](const protocol::Error& e) { on_error(e); });
      if (frame) record(*frame);
      else ++summary_.poses_refused;
      progress.update(i + 1, seconds_since(start));
    }
  }

  // A FrameReady of one of our poses (any of them: latest wins drops some).
  void take(const protocol::Message& m, std::uint64_t first_seq) {
    if (auto* f = std::get_if<protocol::FrameReady>(&m)) {
      const auto it = index_by_time_.find(f->pose.sim_time_s);
      if (f->request_id == 0 && it != index_by_time_.end() && same_pose(f->pose, poses_[it->second])) {
        record(*f);
        last_rendered_ = std::max(last_rendered_, it->second + 1);
      }
    } else if (auto* e = std::get_if<protocol::Error>(&m)) {
      on_error(*e);
      if (e->answers_seq >= first_seq) ++summary_.poses_refused;
    }
  }

  // Poses sent at their log times (relative to the first); frames collected as they come.
  void run_realtime(ClientSession& session, ProgressReporter& progress, Clock::time_point start) {
    const double t0 = poses_.front().sim_time_s;
    std::uint64_t first_seq = 0;
    for (std::size_t i = 0; i < poses_.size(); ++i) {
      const auto due = due_after(start, poses_[i].sim_time_s - t0);
      while (Clock::now() < due)
        if (auto m = session.next(due)) take(*m, first_seq);
      const std::uint64_t seq = session.send(poses_[i]);
      if (first_seq == 0) first_seq = seq;
      ++summary_.poses_sent;
      progress.update(i + 1, seconds_since(start));
    }
    // The last pose is the newest: the service renders it. Wait for it.
    const auto deadline = Clock::now() + o_.frame_timeout;
    while (last_rendered_ < poses_.size() && summary_.poses_refused == 0) {
      if (Clock::now() >= deadline) throw RunError("no frame for the last pose within --frame-timeout");
      if (auto m = session.next(deadline)) take(*m, first_seq);
    }
  }

  void write_sheet() {
    if (files_.empty()) {
      warn(kName, "--contact-sheet: no frame files to show");
      return;
    }
    try {
      write_contact_sheet(files_, o_.contact_sheet);
      std::printf("contact sheet: %s (%zu frames)\n", o_.contact_sheet.c_str(),
                  pick_evenly(files_.size(), kContactSheetMaxFrames).size());
    } catch (const std::exception& e) {
      throw RunError(std::string("--contact-sheet: ") + e.what());
    }
  }

  const ReplayOptions& o_;
  std::vector<protocol::Pose> poses_;
  std::map<double, std::size_t> index_by_time_;  // sim_time_s -> pose index
  std::size_t last_rendered_ = 0;                // realtime: 1 + highest pose index rendered
  ReplaySummary summary_;
  std::vector<SheetFrame> files_;
};

}  // namespace

Command add_replay_command(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Replay a flight log (IGC, Tacview ACMI text, CSV) through the service and report frame rate and latency");
  cmd->add_option("log", args->log, "Flight log: .igc, .acmi / .txt.acmi or .csv (docs/FLIGHT_LOGS.md)")
      ->required()
      ->type_name("LOG");
  cmd->add_option("--connect", args->connect, connect_help())->type_name("ADDR");
  cmd->add_option("--out", args->out,
                  "Directory for the frame files (frame_NNNNNN.png|exr, numbered by the service); created if absent; "
                  "sent to the service as an absolute path, so it must be on the service's machine; default none "
                  "(frames only in the service's shared memory)")
      ->type_name("DIR");
  cmd->add_option("--size", args->size, "Image size in pixels, WxH, each side in [1, 8192]; default 640x360")->type_name("WxH");
  cmd->add_option("--fov", args->fov, "Horizontal field of view, degrees, (0, 170]; default 60")->type_name("DEG");
  cmd->add_option("--fps", args->fps,
                  "Poses per second of log time (the log is resampled at this rate), (0, 1000]; default 10")
      ->type_name("HZ");
  cmd->add_flag("--realtime", args->realtime,
                "Send poses at the pace of their timestamps instead of waiting for each frame; the service renders "
                "the newest pose (latest wins), so there may be fewer frames than poses");
  cmd->add_option("--max-frames", args->max_frames, "Send at most the first N poses, integer >= 1; default all")
      ->type_name("N");
  cmd->add_option("--format", args->format, "Frame file format with --out: png (8-bit sRGB) or exr (linear 32-bit float); default png")
      ->type_name("png|exr");
  cmd->add_option("--contact-sheet", args->contact_sheet,
                  "Also write a PNG mosaic of up to 16 evenly spaced frames (needs --out)")
      ->type_name("FILE.png");
  cmd->add_option("--object", args->object,
                  "ACMI only: the object to follow, a hex id (3000102) or its Name; default the only object with a position")
      ->type_name("ID");
  cmd->add_flag("--skip-out-of-order", args->skip_out_of_order,
                "IGC only: drop fixes whose time goes backwards instead of failing");
  cmd->add_option("--frame-timeout", args->frame_timeout, frame_timeout_help())->type_name("S");
  cmd->footer(std::string(kExitCodesHelp) +
              "\nExample: sim_client replay flight.igc --connect unix:/tmp/cloudsvc.sock --out frames/ --size 640x360 "
              "--fps 10 --contact-sheet contact.png");
  return {cmd, [args]() -> int {
            const ReplayOptions o = validate(*args);
            const PoseTrack track = load_flight_log(o.log, o.log_options);
            std::vector<protocol::Pose> poses = replay_poses(track, o.fps, o.max_frames);
            return Replay(o, std::move(poses)).run();
          }};
}

}  // namespace cloudsvc::sim
