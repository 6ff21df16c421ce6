// Entry point of the flight-log readers: any supported file -> PoseTrack.
#pragma once

#include <string>

#include "sim_client/flight_log_error.h"
#include "sim_client/pose_track.h"

namespace cloudsvc::sim {

struct LogOptions {
  // ACMI only: the object to follow, a hex id ("3000102", "0x3000102") or a Name
  // (case-insensitive). Empty: the file must hold exactly one object with a position.
  std::string acmi_object;
  // IGC only: drop fixes whose UTC time goes backwards (other than the midnight wrap)
  // instead of failing. Repeated fixes (same time) are always dropped.
  bool skip_out_of_order = false;
};

// Reads a flight log, choosing the reader by the file name's extension (ASCII
// case-insensitive):
//   .igc                  IGC (igc_reader.h)
//   .acmi, .txt.acmi      Tacview ACMI 2.x text (acmi_reader.h)
//   .zip.acmi             rejected: "unsupported: zipped ACMI (.zip.acmi); unzip first"
//   .csv                  CSV pose log (csv_reader.h)
// Throws FlightLogError ("<path>:<line>: <problem>", one line) when the file cannot be
// read, its extension is not supported, or the content is malformed, out of range,
// truncated, goes back in time, lacks its header or date, names an unknown object, or
// yields no sample.
PoseTrack load_flight_log(const std::string& path, const LogOptions& options = {});

}  // namespace cloudsvc::sim
