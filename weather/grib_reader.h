// Cloud fields from GRIB2 files, decoded and geolocated by ecCodes (ECMWF's GRIB library;
// no GRIB decoding of our own). Every grid ecCodes geolocates is accepted (grid_field.h
// samples it); each message's validity time (ecCodes validityDate / validityTime: the
// reference time plus the forecast step, the end of a statistical period) dates it.
#pragma once

#include <string>
#include <vector>

#include "weather/grib_cloud_fields.h"
#include "weather/grid_field.h"

namespace cloudsvc::weather {

struct GribCloudMessage {
  CloudFieldRole role;
  double valid_utc_s = 0.0;
  // Values in the renderer's units: cover as a fraction in [0, 1]; bases, tops and
  // orography as geometric height in m above mean sea level, or above the ground when
  // above_ground (heights measured from the ground, not yet corrected by orography).
  // Pressures are converted with the ICAO standard atmosphere and geopotentials with
  // g0 = 9.80665 m/s^2 (standard_atmosphere.h). Missing values (bitmap) are NaN.
  GridField field;
  bool above_ground = false;
  // Profile fields: the level's value (Pa for isobaric levels, m for heights, the level
  // number for hybrid levels) and, for hybrid levels, the vertical coordinate parameters
  // (ecCodes key pv: the a coefficients in Pa, then the b coefficients).
  double level_value = 0.0;
  std::vector<double> pv;
  std::string label;  // "message 3 (tcc, lowCloudLayer)", for messages
};

struct GribReadResult {
  std::vector<GribCloudMessage> clouds;
  int messages = 0;                  // GRIB messages in the file
  std::vector<std::string> ignored;  // shortName of each message that is not a cloud field
};

// Reads every message of a GRIB2 file and keeps its cloud fields. Throws WeatherFileError
// (weather_json.h) with one line "<path>: <problem>": cannot open, not a GRIB file,
// truncated message (with its byte offset), GRIB edition 1, a grid ecCodes cannot geolocate
// or a packing it cannot decode (both named), cloud cover in unknown units, no cloud fields.
GribReadResult read_grib_cloud_fields(const std::string& path);

// True when the path's extension names a GRIB file (.grib2, .grb2, .grib, .grb; any case).
bool is_grib_path(const std::string& path);

}  // namespace cloudsvc::weather
