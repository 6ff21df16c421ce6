// Fuzz target: the Tacview ACMI reader, sim::parse_acmi() (sim_client/acmi_reader.h, with
// the lexer of acmi_lexer.h and the T= parser of acmi_transform.h), on any text, as
// `sim_client replay rec.acmi [--object X]` reads a file. The object to follow is chosen by
// the input's length (size % 4): none (the only object with a position), hex id "1", hex
// id "0x3000102", Name "F-16", so the fuzzer explores every way of choosing one.
// Invariants checked besides the sanitizers':
//  - only FlightLogError is thrown, with a one-line message naming the file and a line of
//    it (fuzz/flight_log_checks.h);
//  - a returned track is non-empty with strictly increasing times and finite, in-range
//    positions (altitude within the readers' limits) and attitudes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz/flight_log_checks.h"
#include "sim_client/acmi_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cloudsvc;
  static const std::string kSource = "fuzz.acmi";
  static const std::array<std::string, 4> kObjects = {"", "1", "0x3000102", "F-16"};
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  sim::AcmiOptions options;
  options.object = kObjects[size % kObjects.size()];
  try {
    fuzz::check_track(sim::parse_acmi(text, kSource, options), fuzz::TrackLimits{});
  } catch (const sim::FlightLogError& e) {
    fuzz::check_error(e, text, kSource);
  }
  return 0;
}
