// What every PoseTrack a flight-log reader returns must satisfy (sim_client/pose_track.h,
// docs/FLIGHT_LOGS.md "Units and frames"), and what its errors must look like
// (sim_client/flight_log_error.h). Shared by the IGC, ACMI and CSV fuzz targets.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "fuzz/fuzz_check.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/pose_track.h"
#include "sim_client/text_input.h"
#include "sim_client/value_checks.h"

namespace cloudsvc::fuzz {

struct TrackLimits {
  // CSV and ACMI check altitudes against [kMinAltitude_m, kMaxAltitude_m]; IGC altitudes
  // are 5-digit fields and are only required to be finite.
  bool altitude_in_log_range = true;
};

inline bool in_range(double v, double lo, double hi) { return v >= lo && v <= hi; }  // false for NaN

// Samples non-empty with strictly increasing finite times; positions and attitudes finite
// and in their documented ranges; velocity finite when present. Then PoseTrack::at() (what
// replay resamples with) between neighbouring samples (the first 64 pairs), for the
// sanitizers.
inline void check_track(const sim::PoseTrack& track, const TrackLimits& limits) {
  FUZZ_CHECK(!track.samples.empty(), "a reader returned an empty track instead of an error");
  for (std::size_t i = 0; i < track.samples.size(); ++i) {
    const sim::PoseSample& s = track.samples[i];
    FUZZ_CHECK(std::isfinite(s.unix_time_s), "a sample time is not finite");
    if (i > 0) {
      FUZZ_CHECK(s.unix_time_s > track.samples[i - 1].unix_time_s, "sample times do not increase strictly");
    }
    FUZZ_CHECK(in_range(s.position.lat_deg, -90.0, 90.0), "latitude outside [-90, 90]");
    FUZZ_CHECK(in_range(s.position.lon_deg, -180.0, 180.0), "longitude outside [-180, 180]");
    FUZZ_CHECK(std::isfinite(s.position.alt_m), "altitude not finite");
    if (limits.altitude_in_log_range) {
      FUZZ_CHECK(in_range(s.position.alt_m, sim::kMinAltitude_m, sim::kMaxAltitude_m),
                 "altitude outside the readers' range");
    }
    FUZZ_CHECK(s.attitude.heading_deg >= 0.0 && s.attitude.heading_deg < 360.0, "heading outside [0, 360)");
    FUZZ_CHECK(in_range(s.attitude.pitch_deg, -90.0, 90.0), "pitch outside [-90, 90]");
    FUZZ_CHECK(s.attitude.roll_deg >= -180.0 && s.attitude.roll_deg < 180.0, "roll outside [-180, 180)");
    if (s.velocity_enu_mps) {
      const auto& v = *s.velocity_enu_mps;
      FUZZ_CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z), "velocity not finite");
    }
  }
  // Interpolation between neighbours: no value checks, PoseTrack::at() leaves antipodal
  // neighbours undefined (pose_track.h) and replay validates every pose it sends.
  for (std::size_t i = 0; i + 1 < track.samples.size() && i < 64; ++i) {
    const double a = track.samples[i].unix_time_s, b = track.samples[i + 1].unix_time_s;
    track.at(a / 2 + b / 2);  // a / 2 + b / 2: no overflow for any finite a, b
  }
}

// One line "<source>:<line>: <problem>", the line within the file (0: the file as a whole).
inline void check_error(const sim::FlightLogError& e, std::string_view text, const std::string& source) {
  const std::string what = e.what();
  FUZZ_CHECK(what.find_first_of("\r\n") == std::string::npos, "a flight-log error is not one line");
  FUZZ_CHECK(what.rfind(source + ":", 0) == 0, "a flight-log error does not start with the file name");
  FUZZ_CHECK(!e.problem().empty(), "a flight-log error without a problem");
  const std::size_t lines = sim::split_lines(text).size();
  FUZZ_CHECK(e.line() <= (lines > 0 ? lines : 1), "a flight-log error names a line after the end of the file");
}

}  // namespace cloudsvc::fuzz
