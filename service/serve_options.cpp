// Flags of `cloudsvc serve` (serve_options.h is the spec): their help text, and the
// conversion of the text CLI11 collected into ServeOptions, with the same one-line error
// contract as render and demo (common/option_values.h).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

#include "common/option_address.h"
#include "common/option_paths.h"
#include "common/option_values.h"
#include "common/option_weather.h"
#include "weather/forecast_weather.h"
#include "protocol/shm/shm_name.h"
#include "renderer/quality_presets.h"
#include "service/cloud_phase_option.h"
#include "service/serve_command_line.h"

namespace cloudsvc::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kMinClients = 1;
constexpr int kMaxClients = 1024;
constexpr int kMaxIdleTimeout_s = 86400;
constexpr int kMinTileBudget_mib = 16;  // one full 1024 x 1024 x 4-channel tile
constexpr int kMaxTileBudget_mib = 65536;

// ---- --listen --------------------------------------------------------------------------

// tcp://HOST:PORT (port 0: any free port) or unix:PATH (option_address.h); a socket path
// must also be bindable: in an existing writable directory, not an existing non-socket
// file (binding there would fail or clobber it).
ListenAddress parse_listen_address(std::string_view flag, const std::string& text) {
  const Endpoint endpoint = parse_endpoint(flag, text, PortUse::Listen);
  ListenAddress address;
  address.text = text;
  if (endpoint.kind == Endpoint::Kind::Tcp) {
    address.kind = ListenAddress::Kind::Tcp;
    address.host = endpoint.host;
    address.port = endpoint.port;
    return address;
  }
  address.kind = ListenAddress::Kind::Unix;
  address.path = endpoint.path;
  const fs::path path(address.path);
  if (!path.has_filename()) fail(flag, text, "socket path names a directory, expected a file name");
  require_writable_directory(flag, text, path.has_parent_path() ? path.parent_path() : ".");
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_socket(status)) {
    fail(flag, text, "exists and is not a socket");
  }
  return address;
}

bool is_wildcard(const ListenAddress& a) { return a.host == "0.0.0.0" || a.host == "::"; }
bool is_ipv6(const ListenAddress& a) { return a.host.find(':') != std::string::npos; }

// True if `a` and `b` cannot both be bound: the same socket path, or the same TCP port
// on the same address or on a wildcard address of the same family.
bool conflicts(const ListenAddress& a, const ListenAddress& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == ListenAddress::Kind::Unix) {
    std::error_code ec;
    return fs::absolute(a.path, ec).lexically_normal() ==
           fs::absolute(b.path, ec).lexically_normal();
  }
  if (a.port == 0 || a.port != b.port || is_ipv6(a) != is_ipv6(b)) return false;  // port 0: each gets its own
  return a.host == b.host || is_wildcard(a) || is_wildcard(b);
}

// A path given on the command line as the service will use it, for telling whether two
// flags name the same file: absolute, lexically normal ("a/./b" is "a/b"), without a trailing
// separator ("frames/" is "frames"); symbolic links are not followed.
fs::path comparable_path(const std::string& text) {
  std::error_code ec;
  fs::path p = fs::absolute(text, ec).lexically_normal();
  if (!p.has_filename() && p.has_relative_path()) p = p.parent_path();
  return p;
}

// The --listen unix: socket at the same path as `text`, if any.
const ListenAddress* unix_socket_at(const std::vector<ListenAddress>& listen, const std::string& text) {
  for (const ListenAddress& l : listen) {
    if (l.kind == ListenAddress::Kind::Unix && comparable_path(l.path) == comparable_path(text)) return &l;
  }
  return nullptr;
}

std::string conflict_reason(const ListenAddress& a, const ListenAddress& earlier) {
  if (a.kind == ListenAddress::Kind::Unix || a.host == earlier.host) {
    return "same address as --listen " + earlier.text + " (each address at most once)";
  }
  return "overlaps --listen " + earlier.text + " (" + (is_ipv6(a) ? "::" : "0.0.0.0") +
         " covers every address of its family on port " + std::to_string(a.port) + ")";
}

// Every --listen value in order; the default address if none was given.
std::vector<ListenAddress> parse_listen_addresses(std::string_view flag,
                                                  const std::vector<std::string>& texts) {
  std::vector<ListenAddress> addresses;
  for (const std::string& text : texts) {
    ListenAddress address = parse_listen_address(flag, text);
    for (const ListenAddress& earlier : addresses) {
      if (conflicts(address, earlier)) fail(flag, text, conflict_reason(address, earlier));
    }
    addresses.push_back(std::move(address));
  }
  if (addresses.empty()) {
    ListenAddress fallback;  // tcp://127.0.0.1:7420
    fallback.text = "tcp://" + fallback.host + ":" + std::to_string(fallback.port);
    addresses.push_back(fallback);
  }
  return addresses;
}

// ---- other values --------------------------------------------------------------------------

// --shm NAME: the shared-memory object "/NAME".
std::string parse_shm_name(std::string_view flag, const std::string& text) {
  if (!valid_shm_name(text)) fail(flag, text, "expected " + shm_name_rule());
  return text;
}

// --socket-mode/--shm-mode OCTAL: permission bits in [0600, 0777] that keep the owner's
// read and write (the service itself must use the object) and set nothing else.
unsigned parse_mode(std::string_view flag, const std::string& text) {
  const std::string expected = "expected octal permissions like 0600 or 0660 (owner read+write required, at most 0777)";
  if (text.empty() || text.size() > 4) fail(flag, text, expected);
  unsigned mode = 0;
  for (char c : text) {
    if (c < '0' || c > '7') fail(flag, text, expected);
    mode = mode * 8 + static_cast<unsigned>(c - '0');
  }
  if (mode > 0777 || (mode & 0600) != 0600) fail(flag, text, expected);
  return mode;
}

// Seconds since the Unix epoch now, from the system clock.
double now_unix_s() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return std::chrono::duration<double>(since_epoch).count();
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

// Raw text of each `serve` flag, as collected by CLI11.
struct ServeCommandLine::Args {
  CLI::App* command = nullptr;
  std::vector<std::string> listen;
  std::string cigi, cigi_host, cigi_mode, cigi_rate, cigi_quality;
  std::vector<std::string> cigi_view_quality;
  std::string shm, shm_max_size, out_dir, time, size, fov, max_clients, exit_after_frames;
  std::vector<std::string> weather;  // --weather: one preset or file, or several forecast files
  std::string socket_mode, shm_mode, idle_timeout, max_view_size, tile_budget, ready_file;
  bool window = false;
  bool cumulus_domes = false;
  bool noise_tiling = false;
  std::string cloud_phase;
};

namespace {

void add_endpoint_flags(CLI::App& cmd, ServeCommandLine::Args& args, const ServeOptions& defaults) {
  cmd.add_option("--listen", args.listen,
                 "Address to accept protocol clients on; repeat for several. tcp://HOST:PORT: "
                 "HOST a numeric IPv4 address, an IPv6 address in brackets ([::1]) or localhost "
                 "(names are not resolved), PORT in [0, 65535] (0: any free port, see --ready-file). unix:PATH: a Unix socket, PATH "
                 "at most 107 bytes in an existing writable directory. A HOST other than "
                 "loopback (e.g. 0.0.0.0) exposes the service, which has no authentication, to "
                 "the network; default tcp://127.0.0.1:7420 (loopback only)")
      ->type_name("ADDR")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.add_option("--socket-mode", args.socket_mode,
                 "Permissions of every Unix socket file, octal (owner read+write required): who "
                 "on this machine may connect and send poses and weather; e.g. 0660 for a group; "
                 "default 0600 (the service's user only)")
      ->type_name("OCTAL");
  cmd.add_option("--idle-timeout", args.idle_timeout,
                 "Disconnect a client that has sent nothing (not even a StatsRequest) for this "
                 "long after its handshake, integer seconds in [0, " + std::to_string(kMaxIdleTimeout_s) +
                     "], 0 = never; default " + std::to_string(defaults.idle_timeout_s))
      ->type_name("S");
  cmd.add_option("--max-view-size", args.max_view_size,
                 "Largest view a client may set, pixels, width x height, each in [" + std::to_string(kMinImageSide) +
                     ", " + std::to_string(kMaxImageSide) + "]; default " +
                     size_text(defaults.max_view_width, defaults.max_view_height))
      ->type_name("WxH");
  cmd.add_option("--tile-budget", args.tile_budget,
                 "Memory for weather-map tiles received but not yet applied by the render thread, "
                 "all clients together, integer MiB in [" + std::to_string(kMinTileBudget_mib) + ", " +
                     std::to_string(kMaxTileBudget_mib) + "]; a tile beyond it is refused with Overloaded; default " +
                     std::to_string(defaults.tile_budget_mib))
      ->type_name("MIB");
  cmd.add_option("--ready-file", args.ready_file,
                 "Once every listener is bound, write the bound addresses (one per line, with the "
                 "port the kernel chose for tcp://HOST:0; with --cigi its udp:HOST:PORT last) to this file, "
                 "atomically; default none")
      ->type_name("PATH");
  cmd.add_option("--max-clients", args.max_clients,
                 "Most clients connected at the same time, integer in [" +
                     std::to_string(kMinClients) + ", " + std::to_string(kMaxClients) +
                     "] (clients); default " + std::to_string(defaults.max_clients))
      ->type_name("N");
}

constexpr double kMaxCigiRate_hz = 1000.0;

void add_cigi_flags(CLI::App& cmd, ServeCommandLine::Args& args) {
  const CigiOptions defaults;
  cmd.add_option("--cigi", args.cigi,
                 "Also be the image generator of a CIGI 3.3 host (docs/CIGI.md): receive its datagrams on this UDP "
                 "address, udp:PORT (loopback) or udp:HOST:PORT (HOST a numeric address; 0.0.0.0 exposes the IG to "
                 "the network), PORT 0: any free port (see --ready-file); each CIGI view is rendered at --size to "
                 "its own ring NAME-view<ID> (--shm NAME) and files (--out-dir DIR/view<ID>/); default none")
      ->type_name("ADDR");
  cmd.add_option("--cigi-host", args.cigi_host,
                 "With --cigi: send Start of Frame and IG Messages to this UDP address, udp:HOST:PORT; default the "
                 "address and port the host's datagrams come from")
      ->type_name("ADDR");
  cmd.add_option("--cigi-mode", args.cigi_mode,
                 "With --cigi: sync (one frame and one Start of Frame per host frame) or async (frames at "
                 "--cigi-rate from the newest state, a Start of Frame each); default sync")
      ->type_name("MODE");
  cmd.add_option("--cigi-rate", args.cigi_rate,
                 numeric_help("With --cigi-mode async: most frames per second (Hz)",
                              Range{0.0, kMaxCigiRate_hz, true, "Hz"}, defaults.rate_hz))
      ->type_name("HZ");
  const std::string presets = join(quality_preset_names(), ", ");
  cmd.add_option("--cigi-quality", args.cigi_quality,
                 "With --cigi: the ray-march quality preset of every view, one of " + presets + "; default " +
                     defaults.quality)
      ->type_name("PRESET");
  cmd.add_option("--cigi-view-quality", args.cigi_view_quality,
                 "With --cigi: the preset of one CIGI view, ID=PRESET (ID 0..65535), over --cigi-quality; "
                 "repeatable. Side channels at low cost about half a default view (docs/CIGI.md, \"Cost of "
                 "several views\")")
      ->type_name("ID=PRESET");
}

void add_sink_flags(CLI::App& cmd, ServeCommandLine::Args& args, const ServeOptions& defaults) {
  cmd.add_option("--shm", args.shm,
                 "Publish every frame in the POSIX shared-memory ring /NAME; NAME 1..200 "
                 "characters from letters, digits, '-', '_', '.'; default none")
      ->type_name("NAME");
  cmd.add_option("--shm-mode", args.shm_mode,
                 "With --shm: permissions of the shared-memory ring, octal (owner read+write "
                 "required): who on this machine may read the aircraft's position and the frames; "
                 "e.g. 0640 for a group; default 0600 (the service's user only)")
      ->type_name("OCTAL");
  cmd.add_option("--shm-max-size", args.shm_max_size,
                 "With --shm: largest frame the ring holds, pixels, width x height, each in [" +
                     std::to_string(kMinImageSide) + ", " + std::to_string(kMaxImageSide) +
                     "]; --size must fit; default " +
                     size_text(defaults.shm_max_width, defaults.shm_max_height))
      ->type_name("WxH");
  cmd.add_flag("--window", args.window,
               "Also show the frames in a window (needs a display); default off");
  cmd.add_option("--out-dir", args.out_dir,
                 "Write every frame as a PNG file into DIR; created if absent (its nearest "
                 "existing parent must be a writable directory); default none (no files)")
      ->type_name("DIR");
}

void add_scene_flags(CLI::App& cmd, ServeCommandLine::Args& args, const ServeOptions& defaults) {
  cmd.add_option("--weather", args.weather,
                 weather_help(defaults.weather_arg, "Weather at start (a forecast's follows the poses); several "
                                                    "GRIB2 or METAR files may follow"))
      ->type_name("PRESET|FILE...");
  cmd.add_flag("--cumulus-domes", args.cumulus_domes,
               "Draw cumulus layers as individual clouds (domes over a placement with a power-law spread of "
               "sizes, docs/MORPHOLOGY.md) instead of the thresholded noise field; slower on llvmpipe; "
               "default off");
  cmd.add_flag("--noise-tiling", args.noise_tiling,
               "Read the cloud noise through its stochastic tiling, so the clouds do not repeat with the "
               "noise's period (docs/MORPHOLOGY.md); the march costs 1.4-1.7x on llvmpipe; default off");
  cmd.add_option("--cloud-phase", args.cloud_phase,
                 cloud_phase_help(defaults.cloud_phase, "on a thread of its own, while the frames go on with the fit"))
      ->type_name("MODEL");
  cmd.add_option("--time", args.time,
                 "Date and time in UTC, ISO 8601 (YYYY-MM-DDTHH:MM[:SS[.fff]]Z or +hh:mm "
                 "offset), years 1900..2199, used until a client sends a time; sets the sun "
                 "position; default the current time (system clock)")
      ->type_name("UTC");
  cmd.add_option("--size", args.size,
                 "View size in pixels until a client sets one, width x height, each in [" +
                     std::to_string(kMinImageSide) + ", " + std::to_string(kMaxImageSide) +
                     "]; default " + size_text(defaults.width, defaults.height))
      ->type_name("WxH");
  cmd.add_option("--fov", args.fov,
                 numeric_help("Horizontal field of view until a client sets one", kFieldOfView,
                              defaults.fov_deg))
      ->type_name("DEG");
  cmd.add_option("--exit-after-frames", args.exit_after_frames,
                 "Stop cleanly after N rendered frames (frames follow client poses and render "
                 "requests), for tests and benchmarks (integer >= 0; 0 = run until SIGINT or "
                 "SIGTERM); default " + std::to_string(defaults.exit_after_frames))
      ->type_name("N");
}

void apply_endpoints(const ServeCommandLine::Args& a, ServeOptions& opt) {
  const CLI::App& cmd = *a.command;
  opt.listen = parse_listen_addresses("--listen", a.listen);
  if (given(cmd, "--max-clients")) {
    opt.max_clients = parse_integer("--max-clients", a.max_clients, kMinClients, kMaxClients, "clients");
  }
  if (given(cmd, "--socket-mode")) opt.socket_mode = parse_mode("--socket-mode", a.socket_mode);
  if (given(cmd, "--idle-timeout"))
    opt.idle_timeout_s = parse_integer("--idle-timeout", a.idle_timeout, 0, kMaxIdleTimeout_s, "seconds");
  if (given(cmd, "--max-view-size"))
    std::tie(opt.max_view_width, opt.max_view_height) = parse_image_size("--max-view-size", a.max_view_size);
  if (given(cmd, "--tile-budget"))
    opt.tile_budget_mib = parse_integer("--tile-budget", a.tile_budget, kMinTileBudget_mib, kMaxTileBudget_mib, "MiB");
  if (given(cmd, "--ready-file")) {
    const fs::path ready(a.ready_file);
    if (!ready.has_filename()) fail("--ready-file", a.ready_file, "names a directory, expected a file name");
    require_writable_directory("--ready-file", a.ready_file, ready.has_parent_path() ? ready.parent_path() : ".");
    // The ready file is renamed into place once the sockets are bound: it would replace a
    // directory (exit 1 after binding), a listening socket of this service or another one.
    std::error_code ec;
    const fs::file_status status = fs::status(ready, ec);
    if (fs::is_directory(status)) fail("--ready-file", a.ready_file, "is a directory, expected a file name");
    if (const ListenAddress* l = unix_socket_at(opt.listen, a.ready_file))
      fail("--ready-file", a.ready_file, "same path as --listen " + l->text + " (the ready file would replace the socket)");
    if (fs::is_socket(status)) fail("--ready-file", a.ready_file, "is a socket (the ready file would replace it)");
    opt.ready_file = a.ready_file;
  }
}

void apply_scene(const ServeCommandLine::Args& a, ServeOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--time")) {
    opt.time_text = a.time;
    opt.unix_time_s = parse_time("--time", a.time);
  } else {
    opt.unix_time_s = now_unix_s();  // time_text stays empty: not given
  }
  const std::vector<std::string> weather_values = weather_flag_values(cmd, a.weather, opt.weather_arg);
  opt.weather_arg = join(weather_values, " ");
  // a forecast's layers follow the poses (service/forecast_tracker.h); none until the first one
  WeatherChoice choice = resolve_weather_choice("--weather", weather_values, opt.unix_time_s);
  opt.forecast = std::move(choice.forecast);
  opt.weather = std::move(choice.weather);
  if (given(cmd, "--size")) std::tie(opt.width, opt.height) = parse_image_size("--size", a.size);
  if (given(cmd, "--fov")) opt.fov_deg = parse_number("--fov", a.fov, kFieldOfView);
  if (given(cmd, "--exit-after-frames")) {
    opt.exit_after_frames = parse_frame_count("--exit-after-frames", a.exit_after_frames,
                                              "0 = run until SIGINT or SIGTERM");
  }
}

// --cigi, --cigi-host, --cigi-mode, --cigi-rate; after apply_sinks (the views' ring names).
void apply_cigi(const ServeCommandLine::Args& a, ServeOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (!given(cmd, "--cigi")) {
    for (const char* flag : {"--cigi-host", "--cigi-mode", "--cigi-rate", "--cigi-quality", "--cigi-view-quality"})
      if (given(cmd, flag)) fail(flag, cmd.get_option(flag)->as<std::string>(), "only valid together with --cigi");
    return;
  }
  CigiOptions c;
  c.listen = parse_udp_endpoint("--cigi", a.cigi, PortUse::Listen);
  if (given(cmd, "--cigi-host")) c.host = parse_udp_endpoint("--cigi-host", a.cigi_host, PortUse::Connect);
  if (given(cmd, "--cigi-mode")) {
    if (a.cigi_mode == "sync") c.pacing = CigiPacing::Synchronous;
    else if (a.cigi_mode == "async") c.pacing = CigiPacing::Asynchronous;
    else fail("--cigi-mode", a.cigi_mode, "expected sync or async");
  }
  if (given(cmd, "--cigi-rate")) {
    c.rate_hz = parse_number("--cigi-rate", a.cigi_rate, Range{0.0, kMaxCigiRate_hz, true, "Hz"});
    if (c.pacing != CigiPacing::Asynchronous) fail("--cigi-rate", a.cigi_rate, "only valid with --cigi-mode async");
  }
  const std::string presets = "expected one of " + join(quality_preset_names(), ", ");
  if (given(cmd, "--cigi-quality")) {
    if (!quality_preset(a.cigi_quality)) fail("--cigi-quality", a.cigi_quality, presets);
    c.quality = a.cigi_quality;
  }
  for (const std::string& item : a.cigi_view_quality) {
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) fail("--cigi-view-quality", item, "expected ID=PRESET, e.g. 1=low");
    const double id = parse_number("--cigi-view-quality", item.substr(0, eq), Range{0.0, 65535.0, false, "view ID"});
    if (id != std::floor(id)) fail("--cigi-view-quality", item, "the view ID is an integer 0..65535");
    const std::string preset = item.substr(eq + 1);
    if (!quality_preset(preset)) fail("--cigi-view-quality", item, presets);
    if (!c.view_quality.emplace(static_cast<int>(id), preset).second)
      fail("--cigi-view-quality", item, "view " + item.substr(0, eq) + " is given twice");
  }
  if (opt.shm_name.size() > kMaxCigiShmBaseChars)
    fail("--shm", opt.shm_name,
         "with --cigi at most " + std::to_string(kMaxCigiShmBaseChars) + " characters (the views' rings add -view<ID>)");
  opt.cigi = c;
}

// --shm, --shm-max-size, --window, --out-dir; after apply_scene (the view must fit the ring).
void apply_sinks(const ServeCommandLine::Args& a, ServeOptions& opt) {
  const CLI::App& cmd = *a.command;
  if (given(cmd, "--shm")) opt.shm_name = parse_shm_name("--shm", a.shm);
  if (given(cmd, "--shm-mode")) {
    opt.shm_mode = parse_mode("--shm-mode", a.shm_mode);
    if (opt.shm_name.empty()) fail("--shm-mode", a.shm_mode, "only valid together with --shm");
  }
  if (given(cmd, "--shm-max-size")) {
    std::tie(opt.shm_max_width, opt.shm_max_height) =
        parse_image_size("--shm-max-size", a.shm_max_size);
    if (opt.shm_name.empty()) fail("--shm-max-size", a.shm_max_size, "only valid together with --shm");
  }
  const bool view_fits = opt.width <= opt.shm_max_width && opt.height <= opt.shm_max_height;
  if (!opt.shm_name.empty() && !view_fits) {
    const std::string limit = size_text(opt.shm_max_width, opt.shm_max_height);
    if (given(cmd, "--size")) {
      fail("--size", a.size, "larger than the shared-memory frame limit " + limit + " (--shm-max-size)");
    }
    fail("--shm-max-size", a.shm_max_size,
         "smaller than the view size " + size_text(opt.width, opt.height) + " (--size)");
  }
  if (opt.width > opt.max_view_width || opt.height > opt.max_view_height) {
    fail(given(cmd, "--size") ? "--size" : "--max-view-size", given(cmd, "--size") ? a.size : a.max_view_size,
         "the view " + size_text(opt.width, opt.height) + " exceeds --max-view-size " +
             size_text(opt.max_view_width, opt.max_view_height));
  }
  opt.window = a.window;
  opt.cumulus_domes = a.cumulus_domes;
  opt.noise_tiling = a.noise_tiling;
  if (given(cmd, "--cloud-phase")) {
    const std::optional<model::CloudPhaseModel> m = model::cloud_phase_model_from_name(a.cloud_phase);
    if (!m) fail("--cloud-phase", a.cloud_phase, "expected fit or mie");
    opt.cloud_phase = *m;
  }
  if (given(cmd, "--out-dir")) {
    check_output_directory("--out-dir", a.out_dir);
    // The directory is made before the sockets are bound: at a socket's path it would make
    // the bind fail (exit 1), at the ready file's the rename.
    if (const ListenAddress* l = unix_socket_at(opt.listen, a.out_dir))
      fail("--out-dir", a.out_dir, "same path as --listen " + l->text + " (a directory cannot be the socket)");
    if (!opt.ready_file.empty() && comparable_path(opt.ready_file) == comparable_path(a.out_dir))
      fail("--out-dir", a.out_dir, "same path as --ready-file " + opt.ready_file);
    opt.out_dir = a.out_dir;
  }
}

}  // namespace

ServeCommandLine::ServeCommandLine(CLI::App& app) : args_(std::make_unique<Args>()) {
  const ServeOptions defaults;
  args_->command = app.add_subcommand(
      "serve",
      "Run as a long-lived image generator: render the views clients request over TCP or Unix "
      "sockets (docs/PROTOCOL.md) into shared memory, files or a window");
  CLI::App& cmd = *args_->command;
  cmd.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  add_endpoint_flags(cmd, *args_, defaults);
  add_sink_flags(cmd, *args_, defaults);
  add_cigi_flags(cmd, *args_);
  add_scene_flags(cmd, *args_, defaults);
  cmd.footer(
      "Example:\n  cloudsvc serve --listen tcp://127.0.0.1:7420 --listen unix:/tmp/cloudsvc.sock "
      "--shm cloudsvc-frames --out-dir frames/\n"
      "Exit codes: 0 clean shutdown on SIGINT or SIGTERM (or after --exit-after-frames), "
      "1 runtime failure (e.g. no GL context, address in use), 2 bad input.");
}

ServeCommandLine::~ServeCommandLine() = default;

bool ServeCommandLine::parsed() const { return args_->command->parsed(); }

ServeOptions ServeCommandLine::validate() const {
  ServeOptions opt;
  apply_endpoints(*args_, opt);
  apply_scene(*args_, opt);
  apply_sinks(*args_, opt);
  apply_cigi(*args_, opt);
  return opt;
}

}  // namespace cloudsvc::cli
