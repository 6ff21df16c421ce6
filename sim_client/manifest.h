// manifest.csv of `sim_client sweep`: one row per rendered entry (columns in
// docs/SIM_CLIENT.md).
#pragma once

#include <cstdint>
#include <string>

#include "sim_client/image_stats.h"

namespace cloudsvc::sim {

struct ManifestRow {
  std::uint64_t frame = 0;  // service frame number
  double lat_deg = 0.0, lon_deg = 0.0, alt_m = 0.0;
  double heading_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;
  double utc_unix_s = 0.0;
  std::string weather;      // label of the weather in effect ("service" = not set by the sweep)
  double render_ms = 0.0, latency_ms = 0.0;
  ImageStats stats;
  std::string file;         // the EXR written by the service
};

// "frame,lat,lon,alt,heading,pitch,roll,utc,weather,render_ms,latency_ms,mean_radiance,cloud_fraction,nonfinite,file"
std::string manifest_header();
// The row without a line break: angles and positions with up to 10 significant digits,
// utc as ISO 8601 (ms), mean_radiance in W m^-2 sr^-1 nm^-1, cloud_fraction in [0, 1],
// text fields quoted when needed.
std::string manifest_line(const ManifestRow& row);

}  // namespace cloudsvc::sim
