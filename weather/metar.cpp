// METAR / SPECI text (metar.h).
#include "weather/metar.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <regex>

#include "geodesy/utc_time.h"
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
  if (!t) throw MetarError("time group '" + std::string(time) + "': no such day in the year before the reference time");
  r.utc_s = *t;
  for (; k < tokens.size(); ++k) {
    const std::string_view g = tokens[k];
    if (g == "RMK" || g == "NOSIG" || g == "BECMG" || g == "TEMPO") break;  // remarks and forecasts
    if (g == "NIL") {
      r.nil = true;
      break;
    }
    if (g == "CLR" || g == "SKC" || g == "NSC" || g == "NCD" || g == "CAVOK") {
      r.clear = true;
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
