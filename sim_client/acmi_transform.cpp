// ACMI T= parsing: 3/5/6/9 '|'-separated fields, empty = unchanged.
#include "sim_client/acmi_transform.h"

#include <vector>

#include "sim_client/flight_log_error.h"
#include "sim_client/text_input.h"
#include "sim_client/value_checks.h"

namespace cloudsvc::sim::acmi {

Transform parse_transform(std::string_view value, const std::string& source, std::size_t line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = value.find('|', start);
    fields.push_back(value.substr(start, bar == std::string_view::npos ? bar : bar - start));
    if (bar == std::string_view::npos) break;
    start = bar + 1;
  }
  const int count = static_cast<int>(fields.size());
  if (count != 3 && count != 5 && count != 6 && count != 9)
    throw FlightLogError(source, line,
                         "malformed T=" + quoted_excerpt(value) + ": " + std::to_string(count) +
                             " fields, expected 3, 5, 6 or 9 '|'-separated fields");

  static constexpr const char* kNames[9] = {"longitude", "latitude", "altitude", "roll",
                                            "pitch",     "yaw",      "U",        "V",
                                            "heading"};
  const bool orientation = count == 6 || count == 9;
  std::optional<double> parsed[9];
  for (int i = 0; i < count; ++i) {
    // Field i of the 5-field form is U/V after Lon|Lat|Alt.
    const int role = (count == 5 && i >= 3) ? i + 3 : i;
    if (trim(fields[static_cast<std::size_t>(i)]).empty()) continue;
    const std::optional<double> v = parse_number(fields[static_cast<std::size_t>(i)]);
    if (!v)
      throw FlightLogError(source, line,
                           std::string("malformed T= ") + kNames[role] + " " +
                               quoted_excerpt(fields[static_cast<std::size_t>(i)]));
    if (auto p = finite_problem(kNames[role], *v)) throw FlightLogError(source, line, *p);
    parsed[role] = v;
  }
  Transform t;
  t.field_count = count;
  t.lon_deg = parsed[0];
  t.lat_deg = parsed[1];
  t.alt_m = parsed[2];
  if (orientation) {
    t.roll_deg = parsed[3];
    t.pitch_deg = parsed[4];
    t.yaw_deg = parsed[5];
  }
  return t;
}

}  // namespace cloudsvc::sim::acmi
