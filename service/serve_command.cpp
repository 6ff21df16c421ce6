// `cloudsvc serve`: network thread (asio: sockets, signals) + render thread (GL), joined
// by the FrameMailbox. See docs/ARCHITECTURE.md ("The service"), docs/PROTOCOL.md and
// docs/RELIABILITY.md (limits, shutdown).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <asio.hpp>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <thread>

#include "protocol/limits.h"
#include "protocol/shm/shm_frame_writer.h"
#include "renderer/quality_presets.h"
#include "service/cigi_endpoint.h"
#include "service/commands.h"
#include "service/frame_mailbox.h"
#include "service/network_server.h"
#include "service/output_directory.h"
#include "service/render_loop.h"
#include "service/view_rings.h"

namespace cloudsvc {

namespace {

// How long SIGINT/SIGTERM wait for the frame in progress before abandoning it, and how
// long the Errors announcing that get to reach the clients: together well inside 2 s.
constexpr auto kShutdownGrace = std::chrono::milliseconds(1200);
constexpr auto kAbandonFlush = std::chrono::milliseconds(300);

protocol::Welcome make_welcome(const ServeOptions& opt) {
  protocol::Welcome w;
  w.service_version = "0.1.0";
  w.capabilities = protocol::capability::kSinkFile | protocol::capability::kWeatherTiles |
                   protocol::capability::kRenderRequest | protocol::capability::kStats;
  if (!opt.shm_name.empty()) w.capabilities |= protocol::capability::kSinkShm;
  if (opt.window) w.capabilities |= protocol::capability::kSinkWindow;
  w.limits = protocol::protocol_limits();
  return w;
}

struct ViewProblem {
  protocol::ErrorCode code = protocol::ErrorCode::SinkUnavailable;
  std::string text;  // empty: the view can be delivered
};

// Checks a SetView against what this service can deliver; on success the view's file_dir
// becomes the resolved directory inside --out-dir.
ViewProblem check_view(protocol::SetView& v, const ServeOptions& opt) {
  using protocol::ErrorCode;
  const std::string size = std::to_string(v.width) + "x" + std::to_string(v.height);
  if (static_cast<int>(v.width) > opt.max_view_width || static_cast<int>(v.height) > opt.max_view_height)
    return {ErrorCode::InvalidField, "SetView.width/height " + size + " exceed the service's --max-view-size " +
                                         std::to_string(opt.max_view_width) + "x" + std::to_string(opt.max_view_height)};
  if ((v.sinks & protocol::sink::kShm) && opt.shm_name.empty())
    return {ErrorCode::SinkUnavailable, "SetView.sinks: shared memory requested but the service runs without --shm"};
  if ((v.sinks & protocol::sink::kShm) &&
      (static_cast<int>(v.width) > opt.shm_max_width || static_cast<int>(v.height) > opt.shm_max_height))
    return {ErrorCode::SinkUnavailable, "SetView.width/height " + size + " exceed the shared-memory ring's " +
                                            std::to_string(opt.shm_max_width) + "x" +
                                            std::to_string(opt.shm_max_height) + " (--shm-max-size)"};
  if ((v.sinks & protocol::sink::kWindow) && !opt.window)
    return {ErrorCode::SinkUnavailable, "SetView.sinks: window requested but the service runs without --window"};
  if (v.sinks & protocol::sink::kFile) {
    const ClientDirectory dir = resolve_client_directory(v.file_dir, opt.out_dir);
    if (!dir.problem.empty()) return {ErrorCode::SinkUnavailable, dir.problem};
    v.file_dir = dir.path.string();
  }
  if (!v.quality_preset.empty() && !quality_preset(v.quality_preset)) {
    std::string names;
    for (const std::string& n : quality_preset_names()) names += (names.empty() ? "" : ", ") + n;
    return {ErrorCode::UnknownPreset, "SetView.quality_preset '" + v.quality_preset + "': unknown (available: " + names + ")"};
  }
  return {};
}

// Writes the bound addresses, one per line, to path: into a fresh temporary in the same
// folder, then renamed, so a reader never sees a partial file.
void write_ready_file(const std::string& path, const std::vector<std::string>& addresses) {
  const std::filesystem::path p(path);
  std::string tmpl = (p.parent_path() / ("." + p.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkostemp(tmpl.data(), O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("--ready-file " + path + ": " + std::strerror(errno));
  std::string text;
  for (const std::string& a : addresses) text += a + "\n";
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) && ::fchmod(fd, 0644) == 0;
  const bool closed = ::close(fd) == 0;
  if (!ok || !closed || ::rename(tmpl.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error("--ready-file " + path + ": " + why);
  }
}

}  // namespace

int run_serve(const ServeOptions& command_line) {
  ServeOptions opt = command_line;
  if (!opt.out_dir.empty()) {
    std::filesystem::create_directories(opt.out_dir);
    opt.out_dir = std::filesystem::canonical(opt.out_dir).string();  // the root every client directory is held to
  }
  // The ring before the sockets: a clash with another service ends this one before it
  // touches any socket path.
  std::unique_ptr<ShmFrameWriter> shm;
  if (!opt.shm_name.empty())
    shm = std::make_unique<ShmFrameWriter>(opt.shm_name, opt.shm_max_width, opt.shm_max_height, opt.shm_mode);
  std::unique_ptr<ViewRings> view_rings;  // the CIGI views' rings, made as views are drawn
  if (opt.cigi && !opt.shm_name.empty())
    view_rings = std::make_unique<ViewRings>(opt.shm_name, opt.shm_max_width, opt.shm_max_height, opt.shm_mode);

  asio::io_context io;
  auto work = asio::make_work_guard(io);
  FrameMailbox mailbox(static_cast<std::size_t>(opt.tile_budget_mib) << 20);
  std::unique_ptr<NetworkServer> server;
  std::unique_ptr<CigiEndpoint> cigi_endpoint;
  std::atomic<bool> stopping{false};
  std::unique_ptr<RenderLoop> loop;
  std::mutex publish_mutex;  // held by the render thread while it writes to a sink
  asio::steady_timer grace_timer(io);
  asio::signal_set signals(io, SIGINT, SIGTERM);

  // The render thread did not finish its frame within the grace: tell the clients, make
  // sure no frame is half written (the ring keeps its last whole frame), remove the socket
  // files and the ring's name, and leave without waiting for the GL work.
  std::chrono::steady_clock::time_point stop_requested;
  auto ms_since_stop = [&] {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stop_requested).count();
  };
  auto abandon_frame = [&] {
    std::printf("cloudsvc serve: the frame in progress did not finish within %lld ms; abandoning it (%.0f ms after "
                "the stop)\n",
                static_cast<long long>(kShutdownGrace.count()), ms_since_stop());
    std::fflush(stdout);
    server->broadcast(protocol::Error{protocol::ErrorCode::RenderFailed,
                                      "the service is shutting down: the frame in progress was abandoned", 0});
    grace_timer.expires_after(kAbandonFlush);
    grace_timer.async_wait([&](const asio::error_code&) {
      publish_mutex.lock();  // a sink write in progress ends first; none starts after
      server->stop();
      if (cigi_endpoint) cigi_endpoint->stop();
      if (shm) shm->unlink_name();
      if (view_rings) view_rings->unlink_names();
      std::printf("cloudsvc serve: stopped after %llu frames (one abandoned), %.0f ms after the stop\n",
                  static_cast<unsigned long long>(loop ? loop->frames_rendered() : 0), ms_since_stop());
      std::fflush(stdout);
      std::_Exit(0);
    });
  };

  // SIGINT/SIGTERM, --exit-after-frames, a closed window, or the render thread's end.
  auto stop_service = [&] {
    asio::post(io, [&] {
      if (stopping.exchange(true)) return;
      stop_requested = std::chrono::steady_clock::now();
      mailbox.request_stop();          // no new frame starts
      if (server) server->stop_listening();  // no new clients; socket files removed
      grace_timer.expires_after(kShutdownGrace);
      grace_timer.async_wait([&](const asio::error_code& ec) {
        if (!ec) abandon_frame();
      });
    });
  };

  const protocol::Welcome welcome = make_welcome(opt);
  NetworkServer::Handler handler = [&](std::uint64_t client, const protocol::Message& m, std::uint64_t seq) {
    if (stopping) return;
    const auto now = std::chrono::steady_clock::now();
    auto overloaded = [&](const std::string& text) {
      server->send_to(client, protocol::Error{protocol::ErrorCode::Overloaded, text, seq});
    };
    std::visit([&](const auto& msg) {
      using T = std::decay_t<decltype(msg)>;
      if constexpr (std::is_same_v<T, protocol::Pose>) {
        mailbox.post_pose(PendingPose{msg, now, client, seq});
      } else if constexpr (std::is_same_v<T, protocol::SetView>) {
        protocol::SetView view = msg;
        const ViewProblem problem = check_view(view, opt);
        if (!problem.text.empty()) server->send_to(client, protocol::Error{problem.code, problem.text, seq});
        else mailbox.post_change(view);
      } else if constexpr (std::is_same_v<T, protocol::WeatherMapTile>) {
        if (!mailbox.post_change(msg))
          overloaded("WeatherMapTile refused: tiles waiting to be applied would exceed the service's --tile-budget of " +
                     std::to_string(opt.tile_budget_mib) + " MiB; send it again after the next FrameReady");
      } else if constexpr (std::is_same_v<T, protocol::SetTime> || std::is_same_v<T, protocol::WeatherLayers>) {
        mailbox.post_change(msg);
      } else if constexpr (std::is_same_v<T, protocol::RenderRequest>) {
        if (!mailbox.post_render(PendingRender{msg.request_id, client, now, seq}))
          overloaded("RenderRequest " + std::to_string(msg.request_id) + " refused: this client already has " +
                     std::to_string(FrameMailbox::kMaxRendersPerClient) +
                     " render requests pending; send the next after a FrameReady");
      } else if constexpr (std::is_same_v<T, protocol::StatsRequest>) {
        protocol::Stats s;
        s.frames_rendered = loop ? loop->frames_rendered() : 0;
        s.fps = loop ? loop->fps() : 0.0;
        s.poses_received = mailbox.poses_received();
        s.poses_dropped = mailbox.poses_dropped();
        s.clients = static_cast<std::uint32_t>(server->client_count());
        s.frame_in_progress_ms = loop ? loop->frame_in_progress_ms() : 0.0;
        server->send_to(client, s);
      } else {
        server->send_to(client, protocol::Error{protocol::ErrorCode::UnexpectedMessage,
                                                std::string(protocol::message_name(m)) + " is not a client message", seq});
      }
    }, m);
  };

  NetworkServer::Config cfg;
  cfg.listen = opt.listen;
  cfg.welcome = welcome;
  cfg.max_clients = opt.max_clients;
  cfg.idle_timeout = std::chrono::seconds(opt.idle_timeout_s);
  cfg.socket_mode = opt.socket_mode;
  server = std::make_unique<NetworkServer>(io, cfg, handler);
  const std::vector<std::string> bound = server->bound_addresses();
  std::vector<std::string> ready = bound;  // the --ready-file lines: the listeners, then the CIGI address
  if (opt.cigi) {
    cigi_endpoint = std::make_unique<CigiEndpoint>(io, *opt.cigi, [&](cigi::HostDatagram d) {
      if (!stopping) mailbox.post_cigi(std::move(d));
    });
    ready.push_back(cigi_endpoint->bound_address());
  }
  if (!opt.ready_file.empty()) write_ready_file(opt.ready_file, ready);  // throws: exit 1, sockets removed

  signals.async_wait([&](const asio::error_code& ec, int sig) {
    if (!ec) {
      std::printf("cloudsvc serve: signal %d, shutting down (a frame in progress gets %lld ms to finish)\n", sig,
                  static_cast<long long>(kShutdownGrace.count()));
      std::fflush(stdout);
      stop_service();
    }
  });
  std::signal(SIGPIPE, SIG_IGN);

  loop = std::make_unique<RenderLoop>(
      opt, mailbox,
      [&](std::optional<std::uint64_t> client, protocol::Message m) {
        asio::post(io, [&, client, m = std::move(m)] {
          if (!server || stopping) return;
          if (client) server->send_to(*client, m);
          else server->broadcast(m);
        });
      },
      stop_service, shm.get(), publish_mutex,
      [&](std::vector<std::uint8_t> bytes) {
        asio::post(io, [&, bytes = std::move(bytes)]() mutable {
          if (cigi_endpoint && !stopping) cigi_endpoint->send(std::move(bytes));
        });
      },
      view_rings.get());

  std::string render_error;
  std::thread render_thread([&] {
    try {
      loop->run();
    } catch (const std::exception& e) {
      render_error = e.what();
    }
    stop_service();
    asio::post(io, [&] {  // after stop_service's own post: everything is in place to close
      grace_timer.cancel();
      server->stop();
      if (cigi_endpoint) cigi_endpoint->stop();
      signals.cancel();
      work.reset();
    });
  });

  for (const std::string& a : bound) std::printf("cloudsvc serve: listening on %s\n", a.c_str());
  if (cigi_endpoint)
    std::printf("cloudsvc serve: CIGI 3.3 image generator on %s (%s)\n", cigi_endpoint->bound_address().c_str(),
                opt.cigi->pacing == CigiPacing::Synchronous ? "synchronous" : "asynchronous");
  if (!opt.shm_name.empty()) std::printf("cloudsvc serve: frames in shared memory /%s\n", opt.shm_name.c_str());
  std::fflush(stdout);
  io.run();
  render_thread.join();
  server.reset();
  if (!render_error.empty()) {
    std::fprintf(stderr, "cloudsvc serve: error: %s\n", render_error.c_str());
    return 1;
  }
  if (cigi_endpoint)
    std::printf("cloudsvc serve: CIGI: %llu datagrams received, %llu packets or datagrams not used, %llu datagrams sent\n",
                static_cast<unsigned long long>(cigi_endpoint->datagrams_received()),
                static_cast<unsigned long long>(loop->cigi_rejections()),
                static_cast<unsigned long long>(cigi_endpoint->datagrams_sent()));
  std::printf("cloudsvc serve: stopped after %llu frames\n", static_cast<unsigned long long>(loop->frames_rendered()));
  return 0;
}

}  // namespace cloudsvc
