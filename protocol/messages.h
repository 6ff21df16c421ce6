// The protocol's messages as plain C++ values, one struct per table of cloudsvc.fbs.
// Units are in the field names (_deg, _m, _s, _mps, _um, _ms); geodetic positions are
// WGS84, altitudes metres above the ellipsoid, UTC times seconds since the Unix epoch.
// Ranges are checked by validate() (validate.h) and listed in docs/PROTOCOL.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "protocol/error_code.h"
#include "protocol/version.h"

namespace cloudsvc::protocol {

// Capability bits (Hello.capabilities, Welcome.capabilities).
namespace capability {
inline constexpr std::uint32_t kSinkShm = 1u << 0;
inline constexpr std::uint32_t kSinkWindow = 1u << 1;
inline constexpr std::uint32_t kSinkFile = 1u << 2;
inline constexpr std::uint32_t kWeatherTiles = 1u << 3;
inline constexpr std::uint32_t kRenderRequest = 1u << 4;
inline constexpr std::uint32_t kStats = 1u << 5;
inline constexpr std::uint32_t kAll = (1u << 6) - 1;
}  // namespace capability

// Output sink bits (SetView.sinks).
namespace sink {
inline constexpr std::uint8_t kShm = 1u << 0;
inline constexpr std::uint8_t kWindow = 1u << 1;
inline constexpr std::uint8_t kFile = 1u << 2;
inline constexpr std::uint8_t kAll = kShm | kWindow | kFile;
}  // namespace sink

// Pose flag bits (Pose.flags).
namespace pose_flag {
inline constexpr std::uint8_t kTeleport = 1u << 0;  // discontinuous jump: drop history
inline constexpr std::uint8_t kReset = 1u << 1;     // reset all per-view state
inline constexpr std::uint8_t kAll = kTeleport | kReset;
}  // namespace pose_flag

// Weather map channel bits (WeatherMapTile.channels). A tile's values are interleaved per
// texel in ascending bit order of the channels present, then its layer-coverage slots
// (WeatherMapTile.layer_channels, bits 0..3) in ascending order.
namespace tile_channel {
inline constexpr std::uint8_t kCoverage = 1u << 0;             // [0, 1], 0.5 = layer's own
inline constexpr std::uint8_t kVerticalDevelopment = 1u << 1;  // [0, 1], 0.5 = layer's own
inline constexpr std::uint8_t kDensity = 1u << 2;              // [0, 1], 0.5 = layer's own
inline constexpr std::uint8_t kPrecipitation = 1u << 3;        // [0, 1], 0 = none
inline constexpr std::uint8_t kGroundAlbedo = 1u << 4;         // [0, 1], grey Lambertian
inline constexpr std::uint8_t kAll = 0x1f;
}  // namespace tile_channel

enum class ShmPixelFormat : std::uint8_t {
  Rgba16fLinear = 0,  // 4 x half float, linear radiance
  Rgba8Srgb = 1,      // 4 x uint8, tone-mapped, sRGB transfer
};

enum class FileFormat : std::uint8_t {
  Png = 0,  // 8-bit sRGB, tone-mapped
  Exr = 1,  // 32-bit float, linear radiance
};

// What a service can take: advertised in Welcome.
struct Limits {
  std::uint32_t max_payload_bytes = 0;  // largest frame payload, bytes
  std::uint32_t max_image_size = 0;     // largest SetView width or height, pixels
  std::uint8_t max_layers = 0;          // most layers in WeatherLayers
  std::uint32_t max_tile_size = 0;      // largest tile width or height, texels
  bool operator==(const Limits&) const = default;
};
// The protocol's own limits (limits.h); a service may advertise smaller ones.
Limits protocol_limits();

// client -> service, first message of a connection.
struct Hello {
  std::uint16_t major = kProtocolMajor;
  std::uint16_t minor = kProtocolMinor;
  std::string client_name;         // for logs, UTF-8
  std::uint32_t capabilities = 0;  // capability bits the client wants
  bool operator==(const Hello&) const = default;
};

// service -> client, answer to Hello.
struct Welcome {
  std::uint16_t major = kProtocolMajor;
  std::uint16_t minor = kProtocolMinor;
  std::string service_version;     // e.g. "0.1.0"
  std::uint32_t capabilities = 0;  // capability bits the service offers
  Limits limits = protocol_limits();
  bool operator==(const Welcome&) const = default;
};

// client -> service: image size, field of view and where frames go.
struct SetView {
  std::uint32_t width = 1280;       // pixels, 1..8192
  std::uint32_t height = 720;       // pixels, 1..8192
  double hfov_deg = 60.0;           // horizontal field of view, (0, 170] deg
  std::uint8_t sinks = sink::kShm;  // sink bits, at least one
  ShmPixelFormat shm_format = ShmPixelFormat::Rgba16fLinear;
  std::string file_dir;  // directory of the file sink (required with sink::kFile)
  FileFormat file_format = FileFormat::Png;
  std::string quality_preset;  // empty = the service's default preset
  bool operator==(const SetView&) const = default;
};

// Velocity in the local East-North-Up frame at the pose, m/s.
struct VelocityEnu {
  double east_mps = 0.0;
  double north_mps = 0.0;
  double up_mps = 0.0;
  bool operator==(const VelocityEnu&) const = default;
};

// client -> service: the eye point. Latest wins (docs/PROTOCOL.md, "Pose semantics").
struct Pose {
  double sim_time_s = 0.0;           // simulation clock, s
  std::optional<double> utc_unix_s;  // UTC of this pose, s since the epoch
  double lat_deg = 0.0;              // geodetic latitude [-90, 90]
  double lon_deg = 0.0;              // longitude [-180, 180]
  double alt_m = 0.0;                // above the WGS84 ellipsoid [-500, 100000]
  double heading_deg = 0.0;          // true heading, clockwise from north [-360, 360]
  double pitch_deg = 0.0;            // nose up positive [-90, 90]
  double roll_deg = 0.0;             // right wing down positive [-180, 180]
  std::optional<VelocityEnu> velocity_enu;
  std::uint8_t flags = 0;  // pose_flag bits
  bool operator==(const Pose&) const = default;
};

// client -> service: UTC for the sun when poses carry none.
struct SetTime {
  double utc_unix_s = 0.0;  // s since the epoch
  bool operator==(const SetTime&) const = default;
};

struct CloudLayer {
  std::uint8_t type = 7;              // CIGI 3.3 cloud type 1..10 (7 = cumulus)
  double base_m = 1000.0;             // layer bottom, m above the ellipsoid
  double top_m = 2000.0;              // layer top, m above the ellipsoid
  double coverage = 0.5;              // [0, 1]
  double density_scale = 1.0;         // multiplier on microphysical extinction [0, 10]
  double droplet_diameter_um = 20.0;  // [5, 50]
  double wind_east_mps = 0.0;         // m/s towards east
  double wind_north_mps = 0.0;        // m/s towards north
  std::int8_t coverage_channel = -1;  // -1 coverage modulated by the map; 0..3 layer-coverage slot (minor 2)
  bool operator==(const CloudLayer&) const = default;
};

// client -> service: the whole layer stack (replaces the previous one).
struct WeatherLayers {
  std::vector<CloudLayer> layers;  // 0..4, sorted by base_m, not overlapping
  std::uint32_t map_seed = 1;      // seed of the procedural global weather map
  std::optional<double> ground_albedo;  // grey Lambertian albedo [0, 1]; unset: the default
  // Horizontal visibility at sea level (meteorological optical range), m, in
  // [weather::kMinVisibility_m, weather::kMaxVisibility_m]; unset: the default haze (166 km).
  std::optional<double> visibility_m;
  bool operator==(const WeatherLayers&) const = default;
};

// client -> service: a georeferenced patch of the weather map. Texel (col, row) covers
// lon in lon_min + [col, col + 1] * (lon_max - lon_min) / width and lat likewise with
// row 0 at the south; value k of that texel is data[(row * width + col) * channels + k].
struct WeatherMapTile {
  double lat_min_deg = 0.0;   // southern edge [-90, 90)
  double lon_min_deg = 0.0;   // western edge [-180, 180)
  double lat_max_deg = 0.0;   // northern edge (lat_min, 90]
  double lon_max_deg = 0.0;   // eastern edge (lon_min, lon_min + 360]; > 180 wraps
  std::uint32_t width = 0;    // texels, 1..1024
  std::uint32_t height = 0;   // texels, 1..1024
  std::uint8_t channels = 0;  // tile_channel bits
  double valid_at_utc_s = 0.0;
  std::vector<float> data;    // height * width * channel_count() values in [0, 1]
  std::uint8_t layer_channels = 0;  // layer-coverage slot bits 0..3 (minor 2); not both empty
  int channel_count() const;  // values per texel: bits set in channels and layer_channels
  bool operator==(const WeatherMapTile&) const = default;
};

// client -> service: render the current state once.
struct RenderRequest {
  std::uint64_t request_id = 0;  // non-zero, echoed in FrameReady
  bool operator==(const RenderRequest&) const = default;
};

// service -> client: a frame reached its sinks.
struct FrameReady {
  std::uint64_t frame_number = 0;
  std::uint64_t request_id = 0;           // 0 for frames driven by poses
  Pose pose;                              // the pose rendered
  double sim_time_s = 0.0;                // = pose.sim_time_s
  std::optional<std::uint32_t> shm_slot;  // ring slot, absent without the shm sink
  std::uint32_t width = 0;                // pixels
  std::uint32_t height = 0;               // pixels
  double render_ms = 0.0;                 // GPU + readback, ms
  double latency_ms = 0.0;                // pose received -> frame delivered, ms
  std::optional<std::string> file_path;   // image written, absent without the file sink
  bool operator==(const FrameReady&) const = default;
};

// either direction.
struct Error {
  ErrorCode code = ErrorCode::Unspecified;
  std::string text;               // one line naming the field
  std::uint64_t answers_seq = 0;  // seq of the message answered, 0 = none
  bool operator==(const Error&) const = default;
};

// client -> service: ask for Stats.
struct StatsRequest {
  bool operator==(const StatsRequest&) const = default;
};

// service -> client.
struct Stats {
  std::uint64_t frames_rendered = 0;
  double fps = 0.0;  // frames per second, recent average
  std::uint64_t poses_received = 0;
  std::uint64_t poses_dropped = 0;  // superseded before being rendered
  std::uint32_t clients = 0;
  double frame_in_progress_ms = 0.0;  // time spent so far on the frame being rendered; 0 when idle (minor 1)
  bool operator==(const Stats&) const = default;
};

// Alternative i is union member i + 1 of Body in cloudsvc.fbs (0 is NONE there).
using Message = std::variant<Hello, Welcome, SetView, Pose, SetTime, WeatherLayers, WeatherMapTile,
                             RenderRequest, FrameReady, Error, StatsRequest, Stats>;

// Table name of the message ("Pose", "FrameReady", ...).
std::string_view message_name(const Message& m);

// Who may send a message. Error goes both ways.
enum class Sender { Client, Service, Either };
Sender sender_of(const Message& m);

}  // namespace cloudsvc::protocol
