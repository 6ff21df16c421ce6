// `sim_client cigi (LOG | --sweep FILE) --ig udp:HOST:PORT`: a CIGI 3.3 host that flies a
// flight log or a sweep through an image generator (`cloudsvc serve --cigi`, or any CIGI 3.3
// IG), one host frame per pose, in either byte order, synchronously (each frame after the
// IG's Start of Frame for the one before) or asynchronously (at --fps). docs/SIM_CLIENT.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "common/option_address.h"
#include "common/option_values.h"
#include "common/option_weather.h"
#include "sim_client/cigi_host_frames.h"
#include "sim_client/cigi_host_link.h"
#include "sim_client/commands.h"
#include "sim_client/flight_log.h"
#include "sim_client/pacing.h"
#include "sim_client/replay_poses.h"
#include "sim_client/sweep_plan.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

constexpr const char* kName = "cigi";
constexpr int kMaxViews = 8;  // what cloudsvc draws (cigi::IgState::kMaxViews)

struct CigiArgs {
  std::string log, sweep, ig, byte_order = "native", mode = "sync", fps = "10", max_frames, views = "1", fov = "60",
                              size = "640x360", weather, object, frame_timeout = kDefaultFrameTimeout_s;
  bool skip_out_of_order = false;
};

struct HostOptions {
  cli::UdpEndpoint ig;
  cigi::ByteOrder order = cigi::kNativeOrder;
  bool synchronous = true;
  double fps = 10.0;
  std::size_t max_frames = 0;
  int views = 1;
  double fov_deg = 60.0, aspect = 9.0 / 16.0;
  std::optional<weather::Weather> weather;
  std::chrono::milliseconds frame_timeout{120000};
};

HostOptions validate(const CigiArgs& a) {
  if (a.log.empty() == a.sweep.empty())
    throw UsageError(a.log.empty() ? "give a flight log (LOG) or --sweep FILE" : "give a flight log or --sweep, not both");
  HostOptions o;
  if (a.ig.empty()) cli::fail("--ig", a.ig, "required: the IG's address, udp:HOST:PORT (cloudsvc serve --cigi)");
  o.ig = cli::parse_udp_endpoint("--ig", a.ig, cli::PortUse::Connect);
  if (a.byte_order == "big") o.order = cigi::ByteOrder::Big;
  else if (a.byte_order == "little") o.order = cigi::ByteOrder::Little;
  else if (a.byte_order != "native") cli::fail("--byte-order", a.byte_order, "expected big, little or native");
  if (a.mode == "async") o.synchronous = false;
  else if (a.mode != "sync") cli::fail("--mode", a.mode, "expected sync or async");
  o.fps = cli::parse_number("--fps", a.fps, cli::Range{0.0, 1000.0, true, "host frames per second"});
  if (!a.max_frames.empty())
    o.max_frames = static_cast<std::size_t>(cli::parse_integer("--max-frames", a.max_frames, 1, 50000000, "frames"));
  o.views = cli::parse_integer("--views", a.views, 1, kMaxViews, "views");
  o.fov_deg = cli::parse_number("--fov", a.fov, cli::Range{0.0, 170.0, true, "degrees"});
  const auto [w, h] = cli::parse_image_size("--size", a.size);
  o.aspect = static_cast<double>(h) / static_cast<double>(w);
  if (!a.weather.empty()) o.weather = cli::resolve_weather("--weather", a.weather);
  o.frame_timeout = std::chrono::milliseconds(static_cast<long long>(parse_frame_timeout(a.frame_timeout) * 1000.0));
  return o;
}

// A sweep's entries as poses (sim time: the entry's index / fps), with their weathers.
std::vector<protocol::Pose> sweep_poses(const SweepPlan& plan, double fps, std::size_t max_frames,
                                        std::vector<const weather::Weather*>& weathers) {
  std::vector<protocol::Pose> poses;
  for (const SweepEntry& e : plan.entries) {
    if (max_frames > 0 && poses.size() == max_frames) break;
    protocol::Pose p;
    p.sim_time_s = static_cast<double>(poses.size()) / fps;
    p.utc_unix_s = e.utc_unix_s;
    p.lat_deg = e.lat_deg;
    p.lon_deg = e.lon_deg;
    p.alt_m = e.alt_m;
    p.heading_deg = e.heading_deg;
    p.pitch_deg = e.pitch_deg;
    p.roll_deg = e.roll_deg;
    poses.push_back(p);
    weathers.push_back(e.weather ? &plan.weathers[*e.weather].weather : nullptr);
  }
  return poses;
}

std::string order_name(cigi::ByteOrder o) { return o == cigi::ByteOrder::Big ? "big-endian" : "little-endian"; }

class CigiHost {
 public:
  CigiHost(const HostOptions& o, std::vector<protocol::Pose> poses, std::vector<const weather::Weather*> weathers)
      : o_(o), poses_(std::move(poses)), weathers_(std::move(weathers)), link_(o.ig),
        views_(side_by_side_views(o.views, o.fov_deg, o.aspect)) {
    if (o_.weather) weathers_.assign(poses_.size(), &*o_.weather);  // --weather: every frame's
  }

  int run() {
    const auto start = Clock::now();
    for (std::size_t i = 0; i < poses_.size(); ++i) {
      const auto datagram = frame_datagram(i);
      link_.send(datagram);
      ++sent_;
      if (o_.synchronous) wait_start_of_frame(static_cast<std::uint32_t>(i + 1), datagram);
      else if (i + 1 < poses_.size()) pace(start, i + 1);  // nothing to pace after the last
    }
    if (!o_.synchronous) wait_start_of_frame(static_cast<std::uint32_t>(poses_.size()), frame_datagram(poses_.size() - 1));
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("cigi: %zu host frames sent (%s, %s), %zu Start of Frame received (IG frames %u-%u), %zu sent again, "
                "%zu IG Messages, %.2f s, %.2f host frames/s\n",
                sent_, order_name(o_.order).c_str(), o_.synchronous ? "synchronous" : "asynchronous", sofs_,
                first_ig_frame_, last_ig_frame_, resent_, messages_, wall, static_cast<double>(poses_.size()) / wall);
    std::fflush(stdout);
    return cli::kExitOk;
  }

 private:
  using Clock = CigiHostLink::Clock;

  std::vector<std::uint8_t> frame_datagram(std::size_t i) {
    HostFrame f;
    f.host_frame = static_cast<std::uint32_t>(i + 1);
    f.last_ig_frame = last_ig_frame_;
    f.pose = poses_[i];
    if (i == 0) {
      f.views = &views_;
      f.view_count = o_.views;
      f.view_hfov_deg = o_.fov_deg;
    }
    const weather::Weather* w = i < weathers_.size() ? weathers_[i] : nullptr;
    if (w && w != weather_sent_) {  // the first frame's, then each change
      f.weather = w;
      weather_sent_ = w;
    }
    try {
      return host_datagram(f, o_.order);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }

  // Reads one IG datagram until the deadline; prints its IG Messages. False at the deadline.
  bool take(Clock::time_point deadline) {
    const std::optional<cigi::IgDatagram> d = link_.receive(deadline);
    if (!d) return false;
    if (!d->usable) {
      for (const cigi::Rejection& r : d->rejections) warn(kName, "unreadable datagram from the IG: " + r.reason);
      return true;
    }
    ++sofs_;
    if (first_ig_frame_ == 0) first_ig_frame_ = d->start_of_frame.ig_frame;
    last_ig_frame_ = d->start_of_frame.ig_frame;
    last_host_frame_seen_ = d->start_of_frame.last_host_frame;
    for (const cigi::IgMessage& m : d->messages) {
      ++messages_;
      warn(kName, "IG: " + m.text);
    }
    return true;
  }

  // Synchronous: until a Start of Frame says the IG has host frame `n`. A Start of Frame
  // of an older host frame (the IG sent its last again: it has not had ours) sends ours again.
  void wait_start_of_frame(std::uint32_t n, const std::vector<std::uint8_t>& datagram) {
    const auto deadline = Clock::now() + o_.frame_timeout;
    while (last_host_frame_seen_ < n) {
      const std::size_t before = sofs_;
      if (!take(deadline))
        throw RunError("no Start of Frame for host frame " + std::to_string(n) + " within --frame-timeout (is "
                       "`cloudsvc serve --cigi " + o_.ig.text() + "` running?)");
      if (sofs_ > before && last_host_frame_seen_ < n && o_.synchronous) {
        link_.send(datagram);
        ++resent_;
      }
    }
  }

  // Asynchronous: frames at --fps of wall time; the IG's datagrams are read meanwhile.
  // Host frame k is due k / fps seconds after the first (due_after: no clock overflow).
  void pace(Clock::time_point start, std::size_t frames_sent) {
    const auto due = due_after(start, static_cast<double>(frames_sent) / o_.fps);
    while (Clock::now() < due)
      if (!take(due)) break;
  }

  const HostOptions& o_;
  std::vector<protocol::Pose> poses_;
  std::vector<const weather::Weather*> weathers_;
  CigiHostLink link_;
  std::vector<cigi::ViewDefinition> views_;
  const weather::Weather* weather_sent_ = nullptr;
  std::size_t sent_ = 0, sofs_ = 0, resent_ = 0, messages_ = 0;
  std::uint32_t first_ig_frame_ = 0, last_ig_frame_ = 0, last_host_frame_seen_ = 0;
};

}  // namespace

Command add_cigi_command(CLI::App& app) {
  auto args = std::make_shared<CigiArgs>();
  CLI::App* cmd = app.add_subcommand(
      kName, "Be a CIGI 3.3 host: fly a flight log (IGC, Tacview ACMI text, CSV) or a sweep through an image generator");
  cmd->add_option("log", args->log, "Flight log: .igc, .acmi / .txt.acmi or .csv (docs/FLIGHT_LOGS.md)")->type_name("LOG");
  cmd->add_option("--sweep", args->sweep, "Instead of a log: a sweep file, .json or .csv (docs/SIM_CLIENT.md, sweep)")
      ->type_name("FILE");
  cmd->add_option("--ig", args->ig, "The image generator's CIGI address, udp:HOST:PORT (udp:PORT: loopback); required")
      ->type_name("ADDR");
  cmd->add_option("--byte-order", args->byte_order,
                  "Byte order of the datagrams sent: big, little or native (this machine's); default native")
      ->type_name("ORDER");
  cmd->add_option("--mode", args->mode,
                  "sync: send each host frame after the IG's Start of Frame for the one before (a lost datagram is "
                  "sent again); async: send at --fps; default sync")
      ->type_name("MODE");
  cmd->add_option("--fps", args->fps,
                  "Host frames per second of log time (the log is resampled at this rate; async: also the send rate), "
                  "(0, 1000]; default 10")
      ->type_name("HZ");
  cmd->add_option("--max-frames", args->max_frames, "Send at most the first N host frames, integer >= 1; default all")
      ->type_name("N");
  cmd->add_option("--views", args->views,
                  "Views (channels) side by side around the nose, each --fov wide, ids 0..N-1, N in [1, 8]; default 1")
      ->type_name("N");
  cmd->add_option("--fov", args->fov, "Horizontal field of view of each view, degrees, (0, 170]; default 60")
      ->type_name("DEG");
  cmd->add_option("--size", args->size,
                  "The IG's image size, WxH (its `serve --size`): the views' vertical field of view keeps its pixels "
                  "square; default 640x360")
      ->type_name("WxH");
  cmd->add_option("--weather", args->weather,
                  "Cloud layers sent as global Weather Control (layers 1-3): a preset or a weather .json; default "
                  "none (the IG's own weather; a sweep's weathers are sent as they change)")
      ->type_name("PRESET|FILE");
  cmd->add_option("--object", args->object, "ACMI only: the object to follow, a hex id or its Name")->type_name("ID");
  cmd->add_flag("--skip-out-of-order", args->skip_out_of_order,
                "IGC only: drop fixes whose time goes backwards instead of failing");
  cmd->add_option("--frame-timeout", args->frame_timeout, frame_timeout_help())->type_name("S");
  cmd->footer(std::string(kExitCodesHelp) +
              "\nExample: cloudsvc serve --cigi udp:8000 --out-dir frames/ & sim_client cigi flight.igc --ig "
              "udp:127.0.0.1:8000 --views 3 --byte-order big");
  return {cmd, [args]() -> int {
            const HostOptions o = validate(*args);
            std::vector<protocol::Pose> poses;
            std::vector<const weather::Weather*> weathers;
            std::optional<SweepPlan> plan;
            if (!args->log.empty()) {
              LogOptions lo;
              lo.acmi_object = args->object;
              lo.skip_out_of_order = args->skip_out_of_order;
              poses = replay_poses(load_flight_log(args->log, lo), o.fps, o.max_frames);
            } else {
              plan = load_sweep(args->sweep);
              poses = sweep_poses(*plan, o.fps, o.max_frames, weathers);
            }
            if (poses.empty()) throw UsageError("no poses to send");
            return CigiHost(o, std::move(poses), std::move(weathers)).run();
          }};
}

}  // namespace cloudsvc::sim
