// CIGI 3.3 packets this image generator reads and writes (Common Image Generator Interface,
// SISO-STD-013-2002 with its 3.3 revision; docs/CIGI.md). Offsets, sizes and bit positions
// are the standard's; units are in the field comments. One UDP datagram carries one message:
// host -> IG messages start with IG Control, IG -> host messages with Start of Frame, and a
// message travels in its sender's byte order, told by the magic number of that first packet.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace cloudsvc::cigi {

inline constexpr std::uint8_t kMajorVersion = 3;
inline constexpr std::uint8_t kMinorVersion = 3;       // what this IG sends (CIGI 3.3)
inline constexpr std::uint8_t kOldestMinorVersion = 2;  // 3.2 has the same IG Control and SOF
inline constexpr std::uint16_t kByteSwapMagic = 0x8000;
// IG Control and Start of Frame timestamps count ticks of 10 µs (a u32: 11.9 hours, then wraps).
inline constexpr double kTimestampTicksPerSecond = 1e5;

// Opcodes (the first byte of every packet; the second is the packet's size in bytes).
namespace opcode {
inline constexpr std::uint8_t kIgControl = 1;
inline constexpr std::uint8_t kEntityControl = 2;
inline constexpr std::uint8_t kComponentControl = 4;
inline constexpr std::uint8_t kShortComponentControl = 5;
inline constexpr std::uint8_t kCelestialSphereControl = 9;
inline constexpr std::uint8_t kAtmosphereControl = 10;
inline constexpr std::uint8_t kEnvironmentalRegionControl = 11;
inline constexpr std::uint8_t kWeatherControl = 12;
inline constexpr std::uint8_t kViewControl = 16;
inline constexpr std::uint8_t kViewDefinition = 21;
inline constexpr std::uint8_t kStartOfFrame = 101;
inline constexpr std::uint8_t kIgMessage = 117;
inline constexpr std::uint8_t kFirstUserDefined = 201;  // 201..255: user-defined packets
}  // namespace opcode

enum class IgMode : std::uint8_t { Standby = 0, Operate = 1, Debug = 2, OfflineMaintenance = 3 };

// Host -> IG, first packet of every host message (24 bytes).
struct IgControl {
  std::uint8_t major_version = kMajorVersion;
  std::uint8_t minor_version = kMinorVersion;
  std::int8_t database = 0;         // database number (0: keep the loaded one)
  IgMode mode = IgMode::Operate;     // 0..2 from a host
  bool timestamp_valid = false;
  bool extrapolation = false;        // extrapolation / interpolation enable (3.3)
  std::uint32_t host_frame = 0;      // the host's frame counter
  std::uint32_t timestamp = 0;       // ticks of 10 µs
  std::uint32_t last_ig_frame = 0;   // the IG frame of the last Start of Frame the host received
  bool operator==(const IgControl&) const = default;
};

// Host -> IG: an entity's pose (48 bytes). Entity 0 is the ownship; the IG draws from it.
struct EntityControl {
  std::uint16_t entity_id = 0;
  std::uint8_t state = 1;           // 0 inactive / standby, 1 active, 2 destroyed
  bool attached = false;            // attached to parent_id: the pose is an offset from it
  std::uint16_t entity_type = 0;
  std::uint16_t parent_id = 0;
  float roll_deg = 0.0f;            // right wing down positive, [-180, 180]
  float pitch_deg = 0.0f;           // nose up positive, [-90, 90]
  float yaw_deg = 0.0f;             // true heading, clockwise from north, [0, 360]
  double lat_deg = 0.0;             // geodetic WGS84 latitude, [-90, 90] (x offset m when attached)
  double lon_deg = 0.0;             // longitude, [-180, 180] (y offset m when attached)
  double alt_m = 0.0;               // altitude above mean sea level, m (z offset m when attached)
  bool operator==(const EntityControl&) const = default;
};

// Host -> IG: a view's eye point relative to its entity (32 bytes). Enable bits: only the
// enabled fields change.
struct ViewControl {
  std::uint16_t view_id = 0;
  std::uint8_t group_id = 0;
  std::uint8_t enable = 0;          // bit 0 x, 1 y, 2 z, 3 roll, 4 pitch, 5 yaw
  std::uint16_t entity_id = 0;
  float x_m = 0.0f, y_m = 0.0f, z_m = 0.0f;  // offsets in the entity's body axes (x forward, y right, z down), m
  float roll_deg = 0.0f, pitch_deg = 0.0f, yaw_deg = 0.0f;  // rotations from the entity's attitude
  bool operator==(const ViewControl&) const = default;
};
namespace view_enable {
inline constexpr std::uint8_t kX = 1, kY = 2, kZ = 4, kRoll = 8, kPitch = 16, kYaw = 32;
}

// Host -> IG: a view's frustum (32 bytes). Enable bits: only the enabled fields change.
struct ViewDefinition {
  std::uint16_t view_id = 0;
  std::uint8_t group_id = 0;
  std::uint8_t enable = 0;          // bit 0 near, 1 far, 2 left, 3 right, 4 top, 5 bottom
  std::uint8_t mirror = 0;          // 0 none, 1 horizontal, 2 vertical, 3 both
  std::uint8_t pixel_replication = 0;
  bool orthographic = false;
  bool reorder = false;
  std::uint8_t view_type = 0;
  float near_m = 0.0f, far_m = 0.0f;  // clipping planes, m
  float left_deg = 0.0f, right_deg = 0.0f, top_deg = 0.0f, bottom_deg = 0.0f;  // half-angles from the view axis (left, bottom < 0 usually)
  bool operator==(const ViewDefinition&) const = default;
};
namespace definition_enable {
inline constexpr std::uint8_t kNear = 1, kFar = 2, kLeft = 4, kRight = 8, kTop = 16, kBottom = 32;
}

// Host -> IG: date and time of the sky (16 bytes).
struct CelestialSphereControl {
  std::uint8_t hour = 12, minute = 0;  // UTC, 0..23 and 0..59
  bool ephemeris = true, sun = true, moon = false, stars = false;
  bool date_valid = false;             // date and time hold; else ignored
  std::uint32_t date = 0;              // MMDDYYYY as a decimal number
  float star_intensity_pct = 100.0f;   // [0, 100]
  bool operator==(const CelestialSphereControl&) const = default;
};

// Host -> IG: the global atmosphere (32 bytes).
struct AtmosphereControl {
  bool model_enable = false;
  std::uint8_t humidity_pct = 0;     // [0, 100]
  float air_temperature_c = 15.0f;
  float visibility_m = 0.0f;         // >= 0
  float wind_horizontal_mps = 0.0f;  // >= 0
  float wind_vertical_mps = 0.0f;
  float wind_direction_deg = 0.0f;   // the wind blows from, clockwise from north, [0, 360]
  float pressure_hpa = 1013.25f;     // >= 0
  bool operator==(const AtmosphereControl&) const = default;
};

// Host -> IG: a region of weather (48 bytes): a rounded rectangle on the ground.
struct EnvironmentalRegionControl {
  std::uint16_t region_id = 0;
  std::uint8_t state = 1;            // 0 inactive, 1 active, 2 destroyed
  std::uint8_t merge = 0;            // bit 0 weather, 1 aerosol, 2 maritime, 3 terrestrial (1 = merge overlapping regions)
  double lat_deg = 0.0, lon_deg = 0.0;  // centre, [-90, 90] and [-180, 180]
  float size_x_m = 0.0f, size_y_m = 0.0f;  // along and across the rotated axes, >= 0
  float corner_radius_m = 0.0f;      // [0, min(size) / 2]
  float rotation_deg = 0.0f;         // of the x axis from north, clockwise, [-180, 180]
  float transition_perimeter_m = 0.0f;  // the band outside the region where its weather fades out, >= 0
  bool operator==(const EnvironmentalRegionControl&) const = default;
};

enum class WeatherScope : std::uint8_t { Global = 0, Regional = 1, Entity = 2 };

// Host -> IG: one weather layer (56 bytes): global, of a region, or around an entity.
// Layer ids: 0 ground fog, 1..3 cloud layers, 4 rain, 5 snow, 6 sleet, 7 hail, 8 sand, 9 dust.
struct WeatherControl {
  std::uint16_t entity_or_region_id = 0;
  std::uint8_t layer_id = 1;
  std::uint8_t humidity_pct = 0;        // [0, 100]
  bool enabled = true;
  bool scud = false, random_winds = false, random_lightning = false;
  std::uint8_t cloud_type = 7;          // 0 none, 1..10 as protocol CloudLayer.type, 11..15 IG-defined
  WeatherScope scope = WeatherScope::Global;
  std::uint8_t severity = 0;            // [0, 5]
  float air_temperature_c = 15.0f;
  float visibility_m = 0.0f;            // >= 0
  float scud_frequency_pct = 0.0f;      // [0, 100]
  float coverage_pct = 50.0f;           // [0, 100]
  float base_elevation_m = 1000.0f;     // above mean sea level
  float thickness_m = 1000.0f;          // >= 0
  float transition_band_m = 0.0f;       // above and below the layer where it fades, >= 0
  float wind_horizontal_mps = 0.0f;     // >= 0
  float wind_vertical_mps = 0.0f;
  float wind_direction_deg = 0.0f;      // the wind blows from, [-360, 360]
  float pressure_hpa = 1013.25f;        // >= 0
  float aerosol_gpm3 = 0.0f;            // >= 0
  bool operator==(const WeatherControl&) const = default;
};
inline constexpr std::uint8_t kFirstCloudLayerId = 1, kLastCloudLayerId = 3;

// IG -> host, first packet of every IG message (24 bytes).
struct StartOfFrame {
  std::uint8_t major_version = kMajorVersion;
  std::uint8_t minor_version = kMinorVersion;
  std::int8_t database = 0;
  std::uint8_t ig_status = 0;        // 0: no error
  IgMode mode = IgMode::Operate;
  bool timestamp_valid = false;
  bool host_earth_model = false;     // false: WGS84
  std::uint32_t ig_frame = 0;        // rises by one each frame
  std::uint32_t timestamp = 0;       // ticks of 10 µs
  std::uint32_t last_host_frame = 0;  // the host frame of the last IG Control received
  bool operator==(const StartOfFrame&) const = default;
};

// IG -> host: a text for the host's operator (4 + text + NUL, padded to 8; at most 104 bytes).
struct IgMessage {
  std::uint16_t message_id = 0;
  std::string text;                  // at most kMaxIgMessageText bytes are sent
  bool operator==(const IgMessage&) const = default;
};
inline constexpr std::size_t kMaxIgMessageText = 99;

// The host -> IG packets the IG honours (after IG Control).
using HostPacket = std::variant<EntityControl, ViewControl, ViewDefinition, CelestialSphereControl, AtmosphereControl,
                                EnvironmentalRegionControl, WeatherControl>;

}  // namespace cloudsvc::cigi
