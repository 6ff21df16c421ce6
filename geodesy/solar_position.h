// Sun position from UTC time and geodetic position: NOAA solar calculator algorithm
// (Meeus, "Astronomical Algorithms", ch. 25, low-precision series as used by the NOAA
// Global Monitoring Laboratory spreadsheet), about 0.01 deg between 1900 and 2100.
#pragma once

namespace cloudsvc::geo {

struct SolarPosition {
  double azimuth_deg = 0.0;    // clockwise from true north, [0, 360)
  double elevation_deg = 0.0;  // geometric (true) elevation above the horizon, no refraction
  double apparent_elevation_deg = 0.0;  // with the NOAA atmospheric refraction correction
  double declination_deg = 0.0;
  double equation_of_time_min = 0.0;
};

// unix_time_s: seconds since 1970-01-01T00:00:00Z (UTC, leap seconds ignored).
SolarPosition solar_position(double unix_time_s, double lat_deg, double lon_deg);

}  // namespace cloudsvc::geo
