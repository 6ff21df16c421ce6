// Fuzz target: the IGC reader, sim::parse_igc() (sim_client/igc_reader.h), on any text, as
// `sim_client replay flight.igc` reads a file (load_flight_log, sim_client/flight_log.h).
// Every input is parsed twice: strictly and with skip_out_of_order.
// Invariants checked besides the sanitizers':
//  - only FlightLogError is thrown, with a one-line message naming the file and a line of
//    it (fuzz/flight_log_checks.h);
//  - a returned track is non-empty with strictly increasing times and finite, in-range
//    positions and attitudes (fuzz/flight_log_checks.h);
//  - skip_out_of_order only drops fixes that make a strict parse fail: when the strict
//    parse succeeds, the lenient one gives the same track.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "fuzz/flight_log_checks.h"
#include "sim_client/igc_reader.h"

namespace {

using namespace cloudsvc;

const std::string kSource = "fuzz.igc";

std::optional<sim::PoseTrack> parse(std::string_view text, bool skip_out_of_order) {
  sim::IgcOptions options;
  options.skip_out_of_order = skip_out_of_order;
  try {
    sim::PoseTrack track = sim::parse_igc(text, kSource, options);
    fuzz::check_track(track, fuzz::TrackLimits{.altitude_in_log_range = false});
    return track;
  } catch (const sim::FlightLogError& e) {
    fuzz::check_error(e, text, kSource);
    return std::nullopt;
  }
}

bool same_samples(const sim::PoseTrack& a, const sim::PoseTrack& b) {
  if (a.samples.size() != b.samples.size()) return false;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    const sim::PoseSample& x = a.samples[i];
    const sim::PoseSample& y = b.samples[i];
    if (x.unix_time_s != y.unix_time_s || x.position.lat_deg != y.position.lat_deg ||
        x.position.lon_deg != y.position.lon_deg || x.position.alt_m != y.position.alt_m ||
        x.attitude.heading_deg != y.attitude.heading_deg || x.attitude.pitch_deg != y.attitude.pitch_deg ||
        x.attitude.roll_deg != y.attitude.roll_deg || x.velocity_enu_mps != y.velocity_enu_mps)
      return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::optional<sim::PoseTrack> strict = parse(text, false);
  const std::optional<sim::PoseTrack> lenient = parse(text, true);
  if (strict) {
    FUZZ_CHECK(lenient && same_samples(*strict, *lenient),
               "skip_out_of_order changed a track that parses strictly");
  }
  return 0;
}
