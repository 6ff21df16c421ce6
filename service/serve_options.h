// Options of `cloudsvc serve`: the long-running image generator (docs/CLI.md,
// docs/PROTOCOL.md). Parsed and validated by parse_command_line (render_options.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/option_address.h"
#include "renderer/model/mie_phase_table.h"
#include "weather/cloud_layer.h"
#include "weather/forecast_weather.h"

namespace cloudsvc {

// One --listen address: "tcp://HOST:PORT" (HOST an IPv4/IPv6 literal or "localhost";
// IPv6 in brackets, e.g. tcp://[::1]:7420) or "unix:PATH" (a Unix stream socket path).
struct ListenAddress {
  enum class Kind { Tcp, Unix } kind = Kind::Tcp;
  std::string host = "127.0.0.1";  // Tcp: numeric address ("localhost" resolved to 127.0.0.1)
  std::uint16_t port = 7420;       // Tcp: 0..65535; 0 = the kernel picks a free port (reported on stdout and in --ready-file)
  std::string path;                // Unix: socket file path (at most 107 bytes)
  std::string text;                // as given, for logs
};

// How a CIGI host paces the IG (docs/CIGI.md, "Synchronous and asynchronous operation").
enum class CigiPacing {
  Synchronous,   // one frame, and one Start of Frame, per host frame (IG Control) received
  Asynchronous,  // frames at the IG's own rate (--cigi-rate) from the newest state
};

// --cigi and its companions: the CIGI 3.3 endpoint (service/cigi_endpoint.h).
struct CigiOptions {
  cli::UdpEndpoint listen;                  // --cigi udp:[HOST:]PORT (host -> IG datagrams)
  std::optional<cli::UdpEndpoint> host;     // --cigi-host: where IG -> host datagrams go; default the sender
  CigiPacing pacing = CigiPacing::Synchronous;  // --cigi-mode sync|async
  double rate_hz = 60.0;                    // --cigi-rate: asynchronous frame rate cap, Hz
  std::string quality = "default";          // --cigi-quality: preset of every view (renderer/quality_presets.h)
  std::map<int, std::string> view_quality;  // --cigi-view-quality ID=PRESET: per CIGI view ID, over `quality`

  // The quality preset name of CIGI view `view_id`.
  const std::string& quality_of(int view_id) const {
    const auto it = view_quality.find(view_id);
    return it == view_quality.end() ? quality : it->second;
  }
};

// Longest ring name with --cigi: each view's ring is NAME-view<ID> (ID up to 65535).
inline constexpr std::size_t kMaxCigiShmBaseChars = 200 - 10;

struct ServeOptions {
  std::vector<ListenAddress> listen;  // --listen, repeatable; default tcp://127.0.0.1:7420 (loopback only)
  std::optional<CigiOptions> cigi;    // --cigi: also an image generator for a CIGI 3.3 host
  std::string shm_name;               // --shm NAME: shared-memory frame ring "/NAME"; empty = none
  int shm_max_width = 1920;           // --shm-max-size WxH: largest frame the ring holds
  int shm_max_height = 1080;
  bool window = false;                // --window: show frames in a GLFW window
  std::string out_dir;                // --out-dir DIR: write every frame there (PNG); empty = no file sink
  std::string weather_arg = "broken-cumulus";  // --weather PRESET|FILE: weather at start
  bool cumulus_domes = false;                  // --cumulus-domes: cumulus layers as individual domes
  bool noise_tiling = false;                   // --noise-tiling: RendererConfig::noise_tiling
  model::CloudPhaseModel cloud_phase = model::CloudPhaseModel::kFit;  // --cloud-phase fit|mie
  weather::Weather weather;                    // resolved (empty with a forecast)
  std::shared_ptr<const weather::ForecastWeather> forecast;  // --weather FILE.grib2|.metar|.txt
  std::string time_text;              // --time UTC ISO 8601 used until a client sends time; default: now
  double unix_time_s = 0.0;           // resolved (now when --time is absent)
  int width = 640;                    // --size WxH: initial view until a client sends SetView
  int height = 360;
  double fov_deg = 60.0;              // --fov: initial horizontal field of view, (0, 170]
  int max_clients = 16;               // --max-clients 1..1024
  // Access and resource bounds (docs/RELIABILITY.md).
  unsigned socket_mode = 0600;        // --socket-mode OCTAL: permissions of every Unix socket file
  unsigned shm_mode = 0600;           // --shm-mode OCTAL: permissions of the shared-memory ring
  int idle_timeout_s = 60;            // --idle-timeout S: a handshaken client silent this long is dropped; 0 = never
  int max_view_width = 3840;          // --max-view-size WxH: largest SetView a client may ask for
  int max_view_height = 2160;
  int tile_budget_mib = 256;          // --tile-budget MIB: weather tiles accepted but not yet applied, all clients
  std::string ready_file;             // --ready-file PATH: written (atomically) once every listener is bound
  int exit_after_frames = 0;          // --exit-after-frames N: stop after N frames (tests, benchmarks); 0 = run until signalled
};

}  // namespace cloudsvc
