// METAR and SPECI aerodrome reports in their published text form (WMO Manual on Codes,
// FM 15 METAR / FM 16 SPECI; ICAO Annex 3, App. 3): the station, the observation time and
// the sky condition, which is all the cloud model uses.
//
// Read: "METAR" or "SPECI" (optional), "COR" (optional), the station's ICAO code, the time
// DDHHMMZ, then groups up to "RMK" or a trend ("NOSIG", "BECMG", "TEMPO"): sky groups
// FEW/SCT/BKN/OVC + height in hundreds of feet above the aerodrome (+ CB or TCU), vertical
// visibility VVhhh (sky obscured), and CLR, SKC, NSC, NCD, CAVOK (no cloud of operational
// significance). Other groups (wind, visibility, weather, temperatures, pressure) are not
// used. A report "NIL" has no observation.
#pragma once

#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::weather {

// A report that cannot be read; what() names the group, quoted.
struct MetarError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SkyGroup {
  enum class Amount { Few, Scattered, Broken, Overcast, Obscured };  // Obscured: VVhhh
  enum class Cloud { Any, Cumulonimbus, ToweringCumulus };
  Amount amount = Amount::Few;
  double height_ft = std::numeric_limits<double>::quiet_NaN();  // above the aerodrome; NaN: "///"
  Cloud cloud = Cloud::Any;
  std::string text;  // the group as written
};

// Fraction of the sky of an amount: the middle of its okta class (FEW 1-2, SCT 3-4, BKN 5-7,
// OVC 8 oktas -> 1.5/8, 3.5/8, 6/8, 1); an obscured sky counts as overcast.
double sky_cover(SkyGroup::Amount a);

struct MetarReport {
  std::string station;           // ICAO code
  int day = 0, hour = 0, minute = 0;
  double utc_s = 0.0;            // observation time, resolved against a reference (parse_metar)
  bool speci = false;
  bool nil = false;              // "NIL": no observation
  bool clear = false;            // CLR, SKC, NSC, NCD or CAVOK
  std::vector<SkyGroup> sky;     // in the report's order (rising heights)
  std::string text;              // the report as read
  int line = 0;                  // its first line in the file (load_metar_file), 0 otherwise
};

// Parses one report. Its day of the month is resolved to the latest date with that day at
// or before reference_utc_s plus one day (reports carry no month or year). Throws
// MetarError: "malformed sky group 'BKN25' (expected ...)", "malformed time group '0512Z'
// (expected DDHHMMZ)", "no station code", ...
MetarReport parse_metar(std::string_view report, double reference_utc_s);

// The reports of a text file: one per line (a report may continue on following lines and
// ends at its line's end or at '='); blank lines and lines starting with '#' are skipped; a
// line "YYYY/MM/DD HH:MM" (as in NOAA's station files) sets the reference time of the
// reports after it, else reference_utc_s holds. Throws WeatherFileError (weather_json.h):
// "<path>: line N: <problem>", or "<path>: no METAR reports".
std::vector<MetarReport> load_metar_file(const std::string& path, double reference_utc_s);

// True when the path's extension names a METAR file (.metar, .txt; any case).
bool is_metar_path(const std::string& path);

}  // namespace cloudsvc::weather
