// Fuzz target: the CSV pose-log reader, sim::parse_csv() (sim_client/csv_reader.h, with
// the RFC 4180 field splitter of csv_fields.h and the ISO 8601 parser of
// geodesy/utc_time.h), on any text, as `sim_client replay poses.csv` reads a file.
// Invariants checked besides the sanitizers':
//  - only FlightLogError is thrown, with a one-line message naming the file and a line of
//    it (fuzz/flight_log_checks.h);
//  - a returned track is non-empty with strictly increasing times and finite, in-range
//    positions (altitude within the readers' limits) and attitudes (heading and roll
//    wrapped into [0, 360) and [-180, 180)).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz/flight_log_checks.h"
#include "sim_client/csv_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cloudsvc;
  static const std::string kSource = "fuzz.csv";
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    fuzz::check_track(sim::parse_csv(text, kSource), fuzz::TrackLimits{});
  } catch (const sim::FlightLogError& e) {
    fuzz::check_error(e, text, kSource);
  }
  return 0;
}
