// load_flight_log: extension dispatch to the IGC, ACMI and CSV readers.
#include "sim_client/flight_log.h"

#include "sim_client/acmi_reader.h"
#include "sim_client/csv_reader.h"
#include "sim_client/igc_reader.h"
#include "sim_client/text_input.h"

namespace cloudsvc::sim {

namespace {

bool has_suffix(const std::string& lower_path, std::string_view suffix) {
  return lower_path.size() >= suffix.size() &&
         lower_path.compare(lower_path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

PoseTrack load_flight_log(const std::string& path, const LogOptions& options) {
  const std::string lower = to_lower_ascii(path);
  if (has_suffix(lower, ".zip.acmi"))
    throw FlightLogError(path, 0, "unsupported: zipped ACMI (.zip.acmi); unzip first");
  if (has_suffix(lower, ".igc")) {
    IgcOptions igc;
    igc.skip_out_of_order = options.skip_out_of_order;
    return parse_igc(read_text_file(path), path, igc);
  }
  if (has_suffix(lower, ".acmi")) {  // also .txt.acmi
    AcmiOptions acmi;
    acmi.object = options.acmi_object;
    return parse_acmi(read_text_file(path), path, acmi);
  }
  if (has_suffix(lower, ".csv")) return parse_csv(read_text_file(path), path);
  throw FlightLogError(path, 0,
                       "unsupported file type: expected .igc, .acmi, .txt.acmi or .csv");
}

}  // namespace cloudsvc::sim
