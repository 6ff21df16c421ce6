// METAR and SPECI aerodrome reports in their published text form (WMO Manual on Codes,
// WMO-No. 306, FM 15 METAR / FM 16 SPECI; ICAO Annex 3, App. 3; the US forms of the Federal
// Meteorological Handbook No. 1, FMH-1, ch. 6 and 12, and the FAA's AIM, ch. 7): the station,
// the observation time, the prevailing visibility and the sky condition, which is all the
// cloud model and its haze use.
//
// Read: "METAR" or "SPECI" (optional), "COR" (optional), the station's ICAO code, the time
// DDHHMMZ, then groups up to "RMK" or a trend ("NOSIG", "BECMG", "TEMPO"):
//   - the prevailing visibility, the first visibility group (FM 15, 15.6): VVVV in metres
//     (9999 is 10 km or more, 0000 less than 50 m), optionally followed by NDV (no
//     directional variation); or statute miles (US, 1 SM = 1609.344 m) ending in SM: whole
//     miles (3SM, 10SM), a fraction (1/2SM), whole miles and a fraction as two groups
//     (1 1/2SM), M for less than (M1/4SM), P for more than (P6SM); "////" is a visibility
//     not observed. A directional minimum visibility after it (VVVV and N, NE, E, SE, S,
//     SW, W or NW, e.g. 1200SW) is not used;
//   - sky groups FEW/SCT/BKN/OVC + height in hundreds of feet above the aerodrome (+ CB or
//     TCU), vertical visibility VVhhh (sky obscured), and CLR, SKC, NSC, NCD, CAVOK (no
//     cloud of operational significance; CAVOK also means a visibility of 10 km or more).
// Other groups (wind, runway visual range, weather, temperatures, pressure) are not used. A
// report "NIL" has no observation.
//
// The visibility drawn (drawn_visibility, weather::Weather::visibility_m; blended between
// aerodromes and in time by station_weather.h): "10 km or more" (9999, CAVOK), more than
// 6 SM (P6SM) and 10 SM or more leave it unset, the model's own clear air, since the true
// visibility is unknown and usually far larger; a smaller value is drawn as reported, except
// that below weather::kMinVisibility_m (fog: 0400, M1/4SM) it is clamped to that least
// visibility the haze draws. The reader has no channel for notes: the report keeps the value
// as reported (MetarReport::visibility_m), so a caller can tell a clamped one.
//
// A group that is unambiguously a visibility group but malformed is an error: 4 digits and
// letters other than a wind's unit (1200SX), or a number, optionally after M or P, ending in
// SM (3/0SM, 11/2SM: whole miles and a fraction are two groups).
#pragma once

#include <limits>
#include <optional>
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
  // Prevailing visibility as reported, m: VVVV (9999: 10000), statute miles x 1609.344 (the
  // bound of M and P: M1/4SM 402 m, P6SM 9656 m), CAVOK 10000; NaN when the report has none
  // (or "////").
  double visibility_m = std::numeric_limits<double>::quiet_NaN();
  // The visibility is a lower bound, "or more": 9999, CAVOK, P..SM, or 10 SM and more.
  bool visibility_or_more = false;
  std::string visibility_text;   // the group as written ("1 1/2SM", "9999NDV", "CAVOK"), else empty
  std::vector<SkyGroup> sky;     // in the report's order (rising heights)
  std::string text;              // the report as read
  int line = 0;                  // its first line in the file (load_metar_file), 0 otherwise
};

// The prevailing visibility to draw (weather::Weather::visibility_m), m: nullopt when the
// report has none or gives "or more" (visibility_or_more: the model's own clear air), else
// visibility_m, at least weather::kMinVisibility_m.
std::optional<double> drawn_visibility(const MetarReport& report);

// Parses one report. Its day of the month is resolved to the latest date with that day at
// or before reference_utc_s plus one day (reports carry no month or year). Throws
// MetarError: "malformed sky group 'BKN25' (expected ...)", "malformed visibility group
// '3/0SM' (expected ...)", "malformed time group '0512Z' (expected DDHHMMZ)", "no station
// code", ...
MetarReport parse_metar(std::string_view report, double reference_utc_s);

// The reports of a text file: one per line (a report may continue on following lines and
// ends at its line's end or at '='); blank lines and lines starting with '#' are skipped; a
// line "YYYY/MM/DD HH:MM" (as in NOAA's station files) sets the reference time of the
// reports after it, else reference_utc_s holds. A UTF-8 byte-order mark at the start of the
// file and CRLF line ends are accepted. Throws WeatherFileError (weather_json.h):
// "<path>: line N: <problem>", or "<path>: no METAR reports".
std::vector<MetarReport> load_metar_file(const std::string& path, double reference_utc_s);

// True when the path's extension names a METAR file (.metar, .txt; any case).
bool is_metar_path(const std::string& path);

}  // namespace cloudsvc::weather
