// CSV sweep files: the flight-log CSV columns plus an optional weather column (sweep_plan.h).
// Unlike a flight log, times may repeat or go backwards: every row is its own view.
#include <array>
#include <cmath>

#include "sim_client/csv_fields.h"
#include "sim_client/sweep_plan.h"
#include "sim_client/sweep_support.h"
#include "sim_client/text_input.h"
#include "sim_client/usage_errors.h"

namespace cloudsvc::sim {

namespace {

constexpr std::array<const char*, 8> kColumns = {"time", "lat", "lon", "alt", "heading", "pitch", "roll", "weather"};
enum Column { kTime, kLat, kLon, kAlt, kHeading, kPitch, kRoll, kWeather };
constexpr std::size_t kRequiredColumns = 7;  // all but weather

class CsvSweepParser {
 public:
  CsvSweepParser(const std::string& source, const std::filesystem::path& base_dir)
      : source_(source), registry_(plan_.weathers, base_dir) {}

  SweepPlan run(std::string_view text) {
    const std::vector<std::string_view> lines = split_lines(text);
    bool have_header = false;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const std::string_view l = trim(lines[k]);
      if (l.empty() || l.front() == '#') continue;
      const std::size_t line = k + 1;
      const auto fields = split_csv_fields(lines[k]);
      if (!fields) fail(line, "malformed row: unterminated quoted field");
      if (!have_header) {
        read_header(line, *fields);
        have_header = true;
        continue;
      }
      if (fields->size() != width_)
        fail(line, "row has " + std::to_string(fields->size()) + " fields, the header has " + std::to_string(width_));
      read_row(line, *fields);
    }
    if (!have_header) fail(lines.size(), "missing header row time,lat,lon,alt,heading,pitch,roll[,weather]");
    if (plan_.entries.empty()) fail(lines.size(), "no data row after the header");
    return std::move(plan_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw UsageError(source_ + ":" + std::to_string(line) + ": " + problem);
  }

  void read_header(std::size_t line, const std::vector<std::string>& names) {
    width_ = names.size();
    index_.fill(-1);
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        if (!iequals(trim(names[i]), kColumns[c])) continue;
        if (index_[c] >= 0) fail(line, std::string("header names column ") + kColumns[c] + " twice");
        index_[c] = static_cast<int>(i);
      }
    for (std::size_t c = 0; c < kRequiredColumns; ++c)
      if (index_[c] < 0)
        fail(line, std::string("header lacks column ") + kColumns[c] +
                       " (required: time,lat,lon,alt,heading,pitch,roll; optional: weather)");
  }

  double number(std::size_t line, const std::vector<std::string>& f, Column c) const {
    const std::string& text = f[static_cast<std::size_t>(index_[c])];
    const std::optional<double> v = parse_number(text);
    if (!v) fail(line, std::string("malformed ") + kColumns[c] + " " + quoted_excerpt(text) + ": expected a number");
    if (!std::isfinite(*v)) fail(line, std::string(kColumns[c]) + " is not finite (" + format_number(*v) + ")");
    return *v;
  }

  void read_row(std::size_t line, const std::vector<std::string>& f) {
    SweepEntry e;
    e.origin = "line " + std::to_string(line);
    const std::string& time_text = f[static_cast<std::size_t>(index_[kTime])];
    const std::optional<double> t = sweep_detail::parse_time_text(time_text);
    if (!t) fail(line, "malformed time " + quoted_excerpt(time_text) + ": expected ISO 8601 UTC or seconds since the Unix epoch");
    e.utc_unix_s = *t;
    e.lat_deg = number(line, f, kLat);
    e.lon_deg = number(line, f, kLon);
    e.alt_m = number(line, f, kAlt);
    e.heading_deg = number(line, f, kHeading);
    e.pitch_deg = number(line, f, kPitch);
    e.roll_deg = number(line, f, kRoll);
    if (index_[kWeather] >= 0) {
      const std::string spec(trim(f[static_cast<std::size_t>(index_[kWeather])]));
      if (!spec.empty()) e.weather = registry_.named(spec, source_ + ":" + std::to_string(line));
    }
    if (auto p = sweep_detail::entry_problem(e)) fail(line, *p);
    if (plan_.entries.size() >= kMaxSweepEntries) fail(line, "more than " + std::to_string(kMaxSweepEntries) + " rows");
    plan_.entries.push_back(std::move(e));
  }

  const std::string& source_;
  SweepPlan plan_;
  sweep_detail::WeatherRegistry registry_;
  std::size_t width_ = 0;
  std::array<int, kColumns.size()> index_{};
};

}  // namespace

SweepPlan parse_sweep_csv(std::string_view text, const std::string& source, const std::filesystem::path& base_dir) {
  return CsvSweepParser(source, base_dir).run(text);
}

}  // namespace cloudsvc::sim
