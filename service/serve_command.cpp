// `cloudsvc serve`: network thread (asio: sockets, signals) + render thread (GL), joined
// by the FrameMailbox. See docs/ARCHITECTURE.md ("The service") and docs/PROTOCOL.md.
#include <unistd.h>

#include <asio.hpp>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "protocol/limits.h"
#include "renderer/quality_presets.h"
#include "service/commands.h"
#include "service/frame_mailbox.h"
#include "service/network_server.h"
#include "service/render_loop.h"

namespace cloudsvc {

namespace {

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

// Checks a SetView against what this service can deliver; empty when it can.
std::string check_view(const protocol::SetView& v, const ServeOptions& opt) {
  if ((v.sinks & protocol::sink::kShm) && opt.shm_name.empty())
    return "SetView.sinks: shared memory requested but the service runs without --shm";
  if ((v.sinks & protocol::sink::kShm) &&
      (static_cast<int>(v.width) > opt.shm_max_width || static_cast<int>(v.height) > opt.shm_max_height))
    return "SetView.width/height " + std::to_string(v.width) + "x" + std::to_string(v.height) +
           " exceed the shared-memory ring's " + std::to_string(opt.shm_max_width) + "x" +
           std::to_string(opt.shm_max_height) + " (--shm-max-size)";
  if ((v.sinks & protocol::sink::kWindow) && !opt.window)
    return "SetView.sinks: window requested but the service runs without --window";
  if (v.sinks & protocol::sink::kFile) {
    std::error_code ec;
    if (v.file_dir.empty() || !std::filesystem::is_directory(v.file_dir, ec) || ::access(v.file_dir.c_str(), W_OK) != 0)
      return "SetView.file_dir '" + v.file_dir + "': not a writable directory on the service's machine";
  }
  if (!v.quality_preset.empty() && !quality_preset(v.quality_preset)) {
    std::string names;
    for (const std::string& n : quality_preset_names()) names += (names.empty() ? "" : ", ") + n;
    return "SetView.quality_preset '" + v.quality_preset + "': unknown (available: " + names + ")";
  }
  return {};
}

}  // namespace

int run_serve(const ServeOptions& opt) {
  if (!opt.out_dir.empty()) std::filesystem::create_directories(opt.out_dir);
  asio::io_context io;
  auto work = asio::make_work_guard(io);
  FrameMailbox mailbox;
  std::unique_ptr<NetworkServer> server;
  std::atomic<bool> stopping{false};
  std::unique_ptr<RenderLoop> loop;

  auto stop_service = [&] {
    asio::post(io, [&] {
      if (stopping.exchange(true)) return;
      mailbox.request_stop();  // the render thread finishes its frame and leaves
      if (server) server->stop();  // no new requests; sockets closed, socket files removed
    });
  };

  const protocol::Welcome welcome = make_welcome(opt);
  NetworkServer::Handler handler = [&](std::uint64_t client, const protocol::Message& m, std::uint64_t seq) {
    if (stopping) return;
    const auto now = std::chrono::steady_clock::now();
    std::visit([&](const auto& msg) {
      using T = std::decay_t<decltype(msg)>;
      if constexpr (std::is_same_v<T, protocol::Pose>) {
        mailbox.post_pose(PendingPose{msg, now, client});
      } else if constexpr (std::is_same_v<T, protocol::SetView>) {
        const std::string problem = check_view(msg, opt);
        if (!problem.empty()) {
          const auto code = problem.find("quality_preset") != std::string::npos ? protocol::ErrorCode::UnknownPreset
                                                                                 : protocol::ErrorCode::SinkUnavailable;
          server->send_to(client, protocol::Error{code, problem, seq});
        } else {
          mailbox.post_change(msg);
        }
      } else if constexpr (std::is_same_v<T, protocol::SetTime> || std::is_same_v<T, protocol::WeatherLayers> ||
                           std::is_same_v<T, protocol::WeatherMapTile>) {
        mailbox.post_change(msg);
      } else if constexpr (std::is_same_v<T, protocol::RenderRequest>) {
        mailbox.post_render(PendingRender{msg.request_id, client, now});
      } else if constexpr (std::is_same_v<T, protocol::StatsRequest>) {
        protocol::Stats s;
        s.frames_rendered = loop ? loop->frames_rendered() : 0;
        s.fps = loop ? loop->fps() : 0.0;
        s.poses_received = mailbox.poses_received();
        s.poses_dropped = mailbox.poses_dropped();
        s.clients = static_cast<std::uint32_t>(server->client_count());
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
  server = std::make_unique<NetworkServer>(io, cfg, handler);

  asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](const asio::error_code& ec, int sig) {
    if (!ec) {
      std::printf("cloudsvc serve: signal %d, finishing the current frame and shutting down\n", sig);
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
      stop_service);

  std::string render_error;
  std::thread render_thread([&] {
    try {
      loop->run();
    } catch (const std::exception& e) {
      render_error = e.what();
    }
    stop_service();
    asio::post(io, [&] {
      signals.cancel();
      work.reset();
    });
  });

  for (const ListenAddress& a : opt.listen) std::printf("cloudsvc serve: listening on %s\n", a.text.c_str());
  if (!opt.shm_name.empty()) std::printf("cloudsvc serve: frames in shared memory /%s\n", opt.shm_name.c_str());
  std::fflush(stdout);
  io.run();
  render_thread.join();
  if (!render_error.empty()) {
    std::fprintf(stderr, "cloudsvc serve: error: %s\n", render_error.c_str());
    return 1;
  }
  std::printf("cloudsvc serve: stopped after %llu frames\n", static_cast<unsigned long long>(loop->frames_rendered()));
  return 0;
}

}  // namespace cloudsvc
