// METAR / SPECI text (metar.h).
#include "weather/metar.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <regex>

#include "geodesy/utc_time.h"
#include "weather/cloud_layer.h"
#include "weather/file_extension.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {

namespace {

bool digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}
int to_int(std::string_view s) {
  int v = 0;
  for (char c : s) v = v * 10 + (c - '0');
  return v;
}

// The latest UTC time with day-of-month `day` and the given time of day at or before
// `limit` (searching back over a year of months).
std::optional<double> latest_date(int day, int hour, int minute, double limit) {
  const std::string ref = geo::format_utc_iso8601(limit);  // YYYY-MM-DDTHH:MM:SSZ
  int year = std::stoi(ref.substr(0, 4)), month = std::stoi(ref.substr(5, 2));
  for (int k = 0; k < 13; ++k) {
    char iso[40];
    std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT%02d:%02d:00Z", year, month, day, hour, minute);
    if (const std::optional<double> t = geo::parse_utc_iso8601(iso); t && *t <= limit) return t;
    if (--month == 0) month = 12, --year;
  }
  return std::nullopt;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

const char* const kSkyFormat =
    "expected FEW, SCT, BKN or OVC with a 3-digit height in hundreds of feet and optionally CB or TCU, e.g. BKN025 "
    "or SCT040CB";

// A sky group, or nullopt when the token is not one; MetarError when it starts like one
// but is malformed.
std::optional<SkyGroup> sky_group(std::string_view t) {
  static const std::regex amount_group("(FEW|SCT|BKN|OVC)([0-9]{3}|///)(CB|TCU|///)?");
  static const std::regex vertical_visibility("VV([0-9]{3}|///)");
  const bool amount_like = (starts_with(t, "FEW") || starts_with(t, "SCT") || starts_with(t, "BKN") || starts_with(t, "OVC"));
  const bool vv_like = starts_with(t, "VV") && t.size() > 2 && (std::isdigit(static_cast<unsigned char>(t[2])) || t[2] == '/');
  if (!amount_like && !vv_like) return std::nullopt;
  std::cmatch m;
  SkyGroup g;
  g.text = std::string(t);
  if (amount_like) {
    if (!std::regex_match(t.data(), t.data() + t.size(), m, amount_group))
      throw MetarError("malformed sky group '" + g.text + "' (" + kSkyFormat + ")");
    const std::string a = m[1].str();
    g.amount = a == "FEW" ? SkyGroup::Amount::Few : a == "SCT" ? SkyGroup::Amount::Scattered
             : a == "BKN" ? SkyGroup::Amount::Broken : SkyGroup::Amount::Overcast;
    if (m[2].str() != "///") g.height_ft = 100.0 * to_int(m[2].str());
    if (m[3].str() == "CB") g.cloud = SkyGroup::Cloud::Cumulonimbus;
    if (m[3].str() == "TCU") g.cloud = SkyGroup::Cloud::ToweringCumulus;
    return g;
  }
  if (!std::regex_match(t.data(), t.data() + t.size(), m, vertical_visibility))
    throw MetarError("malformed vertical visibility group '" + g.text + "' (expected VV and a 3-digit height in hundreds of feet, e.g. VV002)");
  g.amount = SkyGroup::Amount::Obscured;
  if (m[1].str() != "///") g.height_ft = 100.0 * to_int(m[1].str());
  return g;
}

// Visibility groups (WMO-No. 306, FM 15, 15.6; FMH-1, ch. 6 and 12).
constexpr double kStatuteMile_m = 1609.344;  // the international statute mile
constexpr double kWmoOrMore_m = 10000.0;     // VVVV 9999 and CAVOK: 10 km or more
// Automated US stations report at most 10 SM (FMH-1): 10 SM and more counts as a lower bound.
constexpr double kUsOrMore_mi = 10.0;

const char* const kVisibilityFormat =
    "expected 4 digits in metres, optionally with NDV or a direction N, NE, E, SE, S, SW, W or NW, e.g. 0800, "
    "9999NDV or 1200SW, or statute miles ending in SM, e.g. 10SM, 1/2SM, 1 1/2SM, M1/4SM or P6SM";

struct VisibilityGroup {
  double m = std::numeric_limits<double>::quiet_NaN();  // NaN: not observed ("////")
  bool or_more = false;                                 // a lower bound: 9999, P..SM, 10 SM and more
  bool directional = false;  // a directional minimum (1200SW), not the prevailing visibility
  int tokens = 1;            // 2 for whole miles and a fraction ("1 1/2SM")
  std::string text;          // the group as written
};

bool all_letters(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= 'A' && c <= 'Z'; });
}

// Miles of a fraction n/d of a statute mile; MetarError unless a reportable one (FMH-1:
// sixteenths, eighths, quarters, halves, below one mile).
double fraction_miles(const std::string& n, const std::string& d, const std::string& text) {
  const int num = to_int(n), den = to_int(d);
  if (num < 1 || num >= den || (den != 2 && den != 4 && den != 8 && den != 16))
    throw MetarError("malformed visibility group '" + text + "' (" + kVisibilityFormat +
                     "; a fraction is 1/16 to 15/16 of a mile, whole miles apart)");
  return static_cast<double>(num) / den;
}

// A visibility group at token t (next: the token after it, or empty), or nullopt when t is
// not one; MetarError when it is unambiguously one but malformed: 4 digits and letters other
// than a wind's unit (KT, MPS, KMH), or a number, optionally after M or P, ending in SM.
std::optional<VisibilityGroup> visibility_group(std::string_view t, std::string_view next) {
  static const std::regex metres("([0-9]{4})(NDV|N|NE|E|SE|S|SW|W|NW)?");
  // whole miles up to 3 digits: manual stations may report more than 10 SM (15SM, 100SM)
  static const std::regex miles("([MP])?(?:([0-9]{1,3})|([0-9]{1,2})/([0-9]{1,2}))SM");
  static const std::regex whole("[0-9]{1,2}");
  static const std::regex fraction("([0-9]{1,2})/([0-9]{1,2})SM");
  VisibilityGroup v;
  v.text = std::string(t);
  if (t == "////" || t == "////NDV" || t == "////SM") return v;  // not observed (automatic stations)
  std::cmatch m;
  const bool metres_like = t.size() >= 4 && digits(t.substr(0, 4)) &&
                           (t.size() == 4 || (all_letters(t.substr(4)) && t.substr(4) != "KT" &&
                                              t.substr(4) != "MPS" && t.substr(4) != "KMH"));
  if (metres_like) {
    if (!std::regex_match(t.data(), t.data() + t.size(), m, metres))
      throw MetarError("malformed visibility group '" + v.text + "' (" + kVisibilityFormat + ")");
    v.directional = m[2].matched && m[2].str() != "NDV";
    v.or_more = to_int(m[1].str()) == 9999;
    v.m = v.or_more ? kWmoOrMore_m : to_int(m[1].str());  // m; 0000: less than 50 m
    return v;
  }
  std::cmatch f;
  if (std::regex_match(t.data(), t.data() + t.size(), m, whole) && !next.empty() &&
      std::regex_match(next.data(), next.data() + next.size(), f, fraction)) {  // "1 1/2SM"
    v.text += " " + std::string(next);
    v.tokens = 2;
    v.m = (to_int(m[0].str()) + fraction_miles(f[1].str(), f[2].str(), v.text)) * kStatuteMile_m;
    v.or_more = v.m >= kUsOrMore_mi * kStatuteMile_m;
    return v;
  }
  const bool miles_like = t.size() > 2 && t.substr(t.size() - 2) == "SM" &&
                          (std::isdigit(static_cast<unsigned char>(t[0])) ||
                           ((t[0] == 'M' || t[0] == 'P') && std::isdigit(static_cast<unsigned char>(t[1]))));
  if (!miles_like) return std::nullopt;
  if (!std::regex_match(t.data(), t.data() + t.size(), m, miles))
    throw MetarError("malformed visibility group '" + v.text + "' (" + kVisibilityFormat + ")");
  const double mi = m[2].matched ? to_int(m[2].str()) : fraction_miles(m[3].str(), m[4].str(), v.text);
  v.m = mi * kStatuteMile_m;                                // M: less than, P: more than this
  v.or_more = m[1].str() == "P" || mi >= kUsOrMore_mi;
  return v;
}

}  // namespace

double sky_cover(SkyGroup::Amount a) {
  switch (a) {
    case SkyGroup::Amount::Few: return 1.5 / 8.0;
    case SkyGroup::Amount::Scattered: return 3.5 / 8.0;
    case SkyGroup::Amount::Broken: return 6.0 / 8.0;
    case SkyGroup::Amount::Overcast:
    case SkyGroup::Amount::Obscured: return 1.0;
  }
  return 0.0;
}

std::optional<double> drawn_visibility(const MetarReport& report) {
  if (!std::isfinite(report.visibility_m) || report.visibility_or_more) return std::nullopt;
  return std::max(report.visibility_m, kMinVisibility_m);  // fog is clamped: the haze draws no less
}

MetarReport parse_metar(std::string_view report, double reference_utc_s) {
  std::vector<std::string_view> tokens;
  for (std::size_t i = 0; i < report.size();) {
    while (i < report.size() && std::isspace(static_cast<unsigned char>(report[i]))) ++i;
    std::size_t j = i;
    while (j < report.size() && !std::isspace(static_cast<unsigned char>(report[j]))) ++j;
    if (j > i) tokens.push_back(report.substr(i, j - i));
    i = j;
  }
  if (!tokens.empty() && tokens.back() == "=") tokens.pop_back();
  if (!tokens.empty() && tokens.back().size() > 1 && tokens.back().back() == '=')
    tokens.back().remove_suffix(1);
  MetarReport r;
  r.text = std::string(report);
  std::size_t k = 0;
  if (k < tokens.size() && (tokens[k] == "METAR" || tokens[k] == "SPECI")) r.speci = tokens[k++] == "SPECI";
  if (k < tokens.size() && tokens[k] == "COR") ++k;
  static const std::regex station_code("[A-Z][A-Z0-9]{3}");
  if (k >= tokens.size() || !std::regex_match(std::string(tokens[k]), station_code))
    throw MetarError(k < tokens.size() ? "malformed station code '" + std::string(tokens[k]) + "' (expected 4 letters, e.g. LSZH)"
                                       : "empty report");
  r.station = std::string(tokens[k++]);
  if (k >= tokens.size()) throw MetarError("no time group after the station code (expected DDHHMMZ)");
  const std::string_view time = tokens[k++];
  if (time.size() != 7 || time.back() != 'Z' || !digits(time.substr(0, 6)))
    throw MetarError("malformed time group '" + std::string(time) + "' (expected DDHHMMZ, e.g. 051150Z)");
  r.day = to_int(time.substr(0, 2));
  r.hour = to_int(time.substr(2, 2));
  r.minute = to_int(time.substr(4, 2));
  if (r.day < 1 || r.day > 31 || r.hour > 23 || r.minute > 59)
    throw MetarError("time group '" + std::string(time) + "' out of range (day 01-31, hour 00-23, minute 00-59)");
  const std::optional<double> t = latest_date(r.day, r.hour, r.minute, reference_utc_s + 86400.0);
  // every day 01-31 occurs within 13 months back, so only the calendar's start can stop it
  if (!t)
    throw MetarError("time group '" + std::string(time) + "': its latest day " + std::string(time.substr(0, 2)) +
                     " before the reference time falls before 1900-01-01 (times are 1900-2199)");
  r.utc_s = *t;
  bool visibility_read = false;  // the prevailing visibility is the first visibility group
  for (; k < tokens.size(); ++k) {
    const std::string_view g = tokens[k];
    if (g == "RMK" || g == "NOSIG" || g == "BECMG" || g == "TEMPO") break;  // remarks and forecasts
    if (g == "NIL") {
      r.nil = true;
      break;
    }
    if (g == "CLR" || g == "SKC" || g == "NSC" || g == "NCD" || g == "CAVOK") {
      r.clear = true;
      if (g == "CAVOK" && !visibility_read) {  // visibility 10 km or more, no cloud below 5000 ft
        visibility_read = true;
        r.visibility_m = kWmoOrMore_m;
        r.visibility_or_more = true;
        r.visibility_text = "CAVOK";
      }
      continue;
    }
    const std::string_view next = k + 1 < tokens.size() ? tokens[k + 1] : std::string_view();
    if (std::optional<VisibilityGroup> v = visibility_group(g, next)) {
      k += v->tokens - 1;
      if (v->directional || visibility_read) continue;  // a directional minimum, or a second group
      visibility_read = true;
      r.visibility_m = v->m;
      r.visibility_or_more = v->or_more;
      r.visibility_text = v->text;
      continue;
    }
    if (std::optional<SkyGroup> s = sky_group(g)) r.sky.push_back(*s);
  }
  return r;
}

bool is_metar_path(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  return ext == "metar" || ext == "txt";
}

std::vector<MetarReport> load_metar_file(const std::string& path, double reference_utc_s) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw WeatherFileError(path + ": cannot open: " + std::strerror(errno));
  static const std::regex date_line("([0-9]{4})/([0-9]{2})/([0-9]{2}) ([0-9]{2}):([0-9]{2})");
  std::vector<MetarReport> reports;
  std::string line, pending;
  int line_no = 0, pending_line = 0;
  double reference = reference_utc_s;
  const auto flush = [&] {
    if (pending.empty()) return;
    try {
      reports.push_back(parse_metar(pending, reference));
      reports.back().line = pending_line;
    } catch (const MetarError& e) {
      throw WeatherFileError(path + ": line " + std::to_string(pending_line) + ": " + e.what());
    }
    pending.clear();
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string_view l = line;
    // A UTF-8 byte-order mark (files saved by Windows editors) is no part of the first line.
    if (line_no == 1 && l.starts_with("\xEF\xBB\xBF")) l.remove_prefix(3);
    while (!l.empty() && std::isspace(static_cast<unsigned char>(l.front()))) l.remove_prefix(1);
    while (!l.empty() && std::isspace(static_cast<unsigned char>(l.back()))) l.remove_suffix(1);
    if (l.empty() || l.front() == '#') {
      flush();
      continue;
    }
    std::cmatch m;
    if (std::regex_match(l.data(), l.data() + l.size(), m, date_line)) {
      flush();
      const std::string iso = m[1].str() + "-" + m[2].str() + "-" + m[3].str() + "T" + m[4].str() + ":" + m[5].str() + ":00Z";
      const std::optional<double> t = geo::parse_utc_iso8601(iso);
      if (!t) throw WeatherFileError(path + ": line " + std::to_string(line_no) + ": invalid date '" + std::string(l) + "'");
      reference = *t;
      continue;
    }
    // A line starting a new report (METAR/SPECI, or a station code then a time group)
    // ends the pending one; other lines continue it.
    const bool starts_report = starts_with(l, "METAR ") || starts_with(l, "SPECI ") ||
                               std::regex_search(std::string(l.substr(0, 16)), std::regex("^[A-Z][A-Z0-9]{3} [0-9]{6}Z"));
    if (starts_report) flush();
    if (pending.empty()) pending_line = line_no;
    pending += (pending.empty() ? "" : " ") + std::string(l);
    if (l.back() == '=') flush();
  }
  flush();
  if (reports.empty()) throw WeatherFileError(path + ": no METAR reports");
  return reports;
}

}  // namespace cloudsvc::weather
