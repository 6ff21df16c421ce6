// Limits and valid ranges of the wire format. validate() enforces them, Welcome advertises
// the first four, docs/PROTOCOL.md quotes them all. A WeatherMapTile's are the weather
// module's tile rules (weather/map_tile.h), which validate() applies to it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "weather/cloud_layer.h"
#include "weather/map_tile.h"

namespace cloudsvc::protocol {

// ---- sizes ----
// Largest frame payload (one encoded Envelope), bytes: 64 MiB. A frame header announcing
// more is a fatal framing error.
inline constexpr std::uint32_t kMaxPayloadBytes = 64u * 1024u * 1024u;
// Largest SetView width or height, pixels.
inline constexpr std::uint32_t kMaxImageSize = 8192;
// Most cloud layers in WeatherLayers: every layer a valid weather may have
// (weather::kMaxCloudLayers, which the renderer draws too).
inline constexpr std::size_t kMaxLayers = weather::kMaxCloudLayers;
// Largest WeatherMapTile width or height, texels: the weather module's limit, the one rule
// set for tiles (weather/map_tile.h), 1024. 1024 x 1024 x 5 channels x 4 bytes is 20 MiB,
// well inside kMaxPayloadBytes; larger areas are sent as several tiles.
inline constexpr std::uint32_t kMaxTileSize = weather::kMaxTileTexels;
// Longest strings, bytes of UTF-8.
inline constexpr std::size_t kMaxNameBytes = 256;        // Hello.client_name
inline constexpr std::size_t kMaxVersionBytes = 64;      // Welcome.service_version
inline constexpr std::size_t kMaxPresetBytes = 64;       // SetView.quality_preset
inline constexpr std::size_t kMaxPathBytes = 4096;       // SetView.file_dir, FrameReady.file_path
inline constexpr std::size_t kMaxErrorTextBytes = 1024;  // Error.text

// ---- view ----
inline constexpr double kMaxHfov_deg = 170.0;  // horizontal field of view, (0, 170]

// ---- pose ----
inline constexpr double kMinAltitude_m = -500.0;  // above the WGS84 ellipsoid
inline constexpr double kMaxAltitude_m = 100000.0;
inline constexpr double kMaxAbsHeading_deg = 360.0;  // heading in [-360, 360]
inline constexpr double kMaxAbsPitch_deg = 90.0;
inline constexpr double kMaxAbsRoll_deg = 180.0;
inline constexpr double kMaxSpeed_mps = 10000.0;  // |velocity_enu|

// ---- time ----
// UTC seconds since the Unix epoch, years 1900..2199 (the range geodesy's ISO 8601 parser
// and the solar-position code accept): [1900-01-01T00:00Z, 2200-01-01T00:00Z).
inline constexpr double kMinUtc_s = -2208988800.0;
inline constexpr double kMaxUtc_s = 7258118400.0;

// ---- weather layers (the same limits as weather/cloud_layer.h) ----
inline constexpr int kMinCloudType = 1;  // CIGI 3.3: 1 altocumulus ... 10 stratus
inline constexpr int kMaxCloudType = 10;
inline constexpr double kMinLayerBase_m = -500.0;
inline constexpr double kMaxLayerTop_m = 20000.0;
inline constexpr double kMinLayerThickness_m = 10.0;
inline constexpr double kMaxDensityScale = 10.0;
inline constexpr double kMinDropletDiameter_um = 5.0;
inline constexpr double kMaxDropletDiameter_um = 50.0;
inline constexpr double kMaxWindSpeed_mps = 150.0;  // |(wind_east, wind_north)|

}  // namespace cloudsvc::protocol
