// CSV pose-log reader (layout in csv_reader.h).
#include "sim_client/csv_reader.h"

#include <array>
#include <cstdio>
#include <optional>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/angles.h"
#include "sim_client/csv_fields.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/text_input.h"
#include "sim_client/value_checks.h"

namespace cloudsvc::sim {

namespace {

constexpr std::array<const char*, 7> kColumns = {"time",    "lat",   "lon", "alt",
                                                 "heading", "pitch", "roll"};
enum Column { kTime, kLat, kLon, kAlt, kHeading, kPitch, kRoll };

// Longitudes accepted, degrees: one turn either way, wrapped into [-180, 180). A track
// counted on past +-180 (across the antimeridian) or the 0..360 convention reads as meant;
// a larger magnitude is not a longitude anyone writes but a corrupt value.
constexpr double kMaxLongitude_deg = 360.0;

// "1714564801.500 s (2024-05-01T12:00:02Z)" for messages.
std::string describe_time(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  std::string out = buf;
  out += " (";
  out += geo::format_utc_iso8601(t);
  out += ')';
  return out;
}

class CsvParser {
 public:
  CsvParser(std::string_view text, const std::string& source)
      : lines_(split_lines(text)), source_(source) {}

  PoseTrack run() {
    std::size_t last_data_line = lines_.size();
    while (last_data_line > 0 && skipped(lines_[last_data_line - 1])) --last_data_line;
    bool have_header = false;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      if (skipped(lines_[k])) continue;
      const std::size_t line = k + 1;
      std::vector<std::string> fields = split_fields(line, lines_[k]);
      if (!have_header) {
        read_header(line, fields);
        have_header = true;
      } else {
        if (fields.size() != width_) {
          const std::string counts = std::to_string(fields.size()) + " fields, the header has " +
                                     std::to_string(width_);
          if (line == last_data_line) fail(line, "truncated file: last row has " + counts);
          fail(line, "malformed row: " + counts);
        }
        read_row(line, fields);
      }
    }
    if (!have_header)
      fail(lines_.size(), "missing header row time,lat,lon,alt,heading,pitch,roll");
    if (track_.samples.empty()) fail(lines_.size(), "no data row after the header: empty track");
    track_.source = source_;
    return std::move(track_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw FlightLogError(source_, line, problem);
  }

  static bool skipped(std::string_view l) {
    l = trim(l);
    return l.empty() || l.front() == '#';
  }

  // RFC 4180 fields of one line (csv_fields.h: quoted fields may hold commas and
  // doubled quotes).
  std::vector<std::string> split_fields(std::size_t line, std::string_view l) const {
    auto fields = split_csv_fields(l);
    if (!fields) fail(line, "malformed row: unterminated quoted field");
    return *fields;
  }

  void read_header(std::size_t line, const std::vector<std::string>& names) {
    width_ = names.size();
    index_.fill(-1);
    for (std::size_t i = 0; i < names.size(); ++i) {
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        if (!iequals(trim(names[i]), kColumns[c])) continue;
        if (index_[c] >= 0)
          fail(line, std::string("header names column ") + kColumns[c] + " twice");
        index_[c] = static_cast<int>(i);
      }
    }
    std::string missing;
    for (std::size_t c = 0; c < kColumns.size(); ++c)
      if (index_[c] < 0) {
        if (!missing.empty()) missing += ',';
        missing += kColumns[c];
      }
    if (!missing.empty())
      fail(line, "missing header row time,lat,lon,alt,heading,pitch,roll: no column " + missing +
                     " in " + quoted_excerpt(lines_[line - 1]));
  }

  const std::string& field(const std::vector<std::string>& f, Column c) const {
    return f[static_cast<std::size_t>(index_[c])];
  }

  double number(std::size_t line, const std::vector<std::string>& f, Column c) const {
    const std::optional<double> v = parse_number(field(f, c));
    if (!v)
      fail(line, std::string("malformed ") + kColumns[c] + " " + quoted_excerpt(field(f, c)) +
                     ": expected a number");
    return *v;
  }

  double time(std::size_t line, const std::vector<std::string>& f) const {
    const std::string_view text = trim(field(f, kTime));
    std::optional<double> t = parse_number(text);
    if (!t) t = geo::parse_utc_iso8601(text);
    if (!t)
      fail(line, "malformed time " + quoted_excerpt(text) +
                     ": expected ISO 8601 UTC or seconds since the Unix epoch");
    if (auto p = range_problem("time", *t, kMinUnixTime, kEndUnixTime)) fail(line, *p);
    return *t;
  }

  void read_row(std::size_t line, const std::vector<std::string>& f) {
    PoseSample s;
    s.unix_time_s = time(line, f);
    s.position.lat_deg = number(line, f, kLat);
    s.position.lon_deg = number(line, f, kLon);
    s.position.alt_m = number(line, f, kAlt);
    const double heading = number(line, f, kHeading);
    s.attitude.pitch_deg = number(line, f, kPitch);
    const double roll = number(line, f, kRoll);
    std::optional<std::string> p;
    if ((p = range_problem("lat", s.position.lat_deg, -90.0, 90.0)) ||
        (p = range_problem("lon", s.position.lon_deg, -kMaxLongitude_deg, kMaxLongitude_deg)) ||
        (p = range_problem("alt", s.position.alt_m, kMinAltitude_m, kMaxAltitude_m)) ||
        (p = finite_problem("heading", heading)) ||
        (p = range_problem("pitch", s.attitude.pitch_deg, -90.0, 90.0)) ||
        (p = finite_problem("roll", roll)))
      fail(line, *p);
    s.position.lon_deg = wrap_lon_deg(s.position.lon_deg);
    s.attitude.heading_deg = wrap_deg_360(heading);
    s.attitude.roll_deg = wrap_deg_180(roll);

    if (!track_.samples.empty() && s.unix_time_s <= track_.samples.back().unix_time_s) {
      const char* what = s.unix_time_s == track_.samples.back().unix_time_s
                             ? "time repeats: "
                             : "time goes backwards: ";
      fail(line, what + describe_time(s.unix_time_s) + " after " +
                     describe_time(track_.samples.back().unix_time_s) + " (line " +
                     std::to_string(last_line_) + ")");
    }
    last_line_ = line;
    track_.samples.push_back(s);
  }

  std::vector<std::string_view> lines_;
  const std::string& source_;
  std::size_t width_ = 0;            // header field count
  std::array<int, 7> index_{};       // field index of each required column
  std::size_t last_line_ = 0;        // line of the last row read
  PoseTrack track_;
};

}  // namespace

PoseTrack parse_csv(std::string_view text, const std::string& source) {
  return CsvParser(text, source).run();
}

}  // namespace cloudsvc::sim
