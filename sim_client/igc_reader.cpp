// IGC reader: A/HFDTE/B records -> PoseTrack (format notes in igc_reader.h).
#include "sim_client/igc_reader.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "geodesy/utc_time.h"
#include "sim_client/angles.h"
#include "sim_client/flight_log_error.h"
#include "sim_client/text_input.h"

namespace cloudsvc::sim {

namespace {

constexpr std::size_t kFixLength = 35;       // B record without extensions
constexpr double kSecondsPerDay = 86400.0;
constexpr double kMidnightWrapMin = 43200.0;  // a decrease of more than 12 h is a new day

// A B record as written, before altitude selection.
struct RawFix {
  std::size_t line = 0;
  double unix_time_s = 0.0;
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  bool fix_3d = false;  // validity 'A'
  int pressure_alt_m = 0;
  int gnss_alt_m = 0;
};

// Exactly the characters of s as an unsigned decimal number (s non-empty, digits only).
bool unsigned_digits(std::string_view s, int& out) {
  if (s.empty()) return false;
  int v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  out = v;
  return true;
}

// A 5-byte IGC altitude: "01234" or "-0123".
bool altitude_field(std::string_view s, int& out) {
  if (!s.empty() && s.front() == '-') {
    if (!unsigned_digits(s.substr(1), out)) return false;
    out = -out;
    return true;
  }
  return unsigned_digits(s, out);
}

class IgcParser {
 public:
  IgcParser(std::string_view text, const std::string& source, const IgcOptions& options)
      : lines_(split_lines(text)), source_(source), options_(options) {}

  PoseTrack run() {
    check_a_record();
    std::size_t last_record = lines_.size();
    while (last_record > 0 && trim(lines_[last_record - 1]).empty()) --last_record;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const std::string_view rec = lines_[k];
      const std::size_t line = k + 1;
      if (rec.size() >= 5 && rec[0] == 'H' && rec.substr(2, 3) == "DTE") {
        if (!day_start_) parse_date(line, rec);
      } else if (!rec.empty() && rec[0] == 'B') {
        parse_fix(line, rec, line == last_record);
      }
    }
    if (fixes_.empty()) fail(lines_.size(), "no B record (fix) in the file: empty track");
    return build_track();
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw FlightLogError(source_, line, problem);
  }

  void check_a_record() const {
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      if (trim(lines_[k]).empty()) continue;
      if (lines_[k][0] != 'A')
        fail(k + 1, "missing A record: an IGC file starts with the A (manufacturer) record, "
                    "found " + quoted_excerpt(lines_[k]));
      return;
    }
    fail(0, "empty file: no IGC records");
  }

  // "HFDTEDDMMYY" or "HFDTEDATE:DDMMYY[,NN]" -> UTC midnight of that date.
  void parse_date(std::size_t line, std::string_view rec) {
    std::string_view rest = rec.substr(5);
    if (rest.substr(0, 4) == "DATE") rest.remove_prefix(4);
    if (!rest.empty() && rest.front() == ':') rest.remove_prefix(1);
    rest = trim(rest);
    int dd = 0, mm = 0, yy = 0;
    const std::string_view tail = rest.size() >= 6 ? rest.substr(6) : std::string_view();
    if (rest.size() < 6 || !unsigned_digits(rest.substr(0, 2), dd) ||
        !unsigned_digits(rest.substr(2, 2), mm) || !unsigned_digits(rest.substr(4, 2), yy) ||
        !(tail.empty() || tail.front() == ',' || tail.front() == ' '))
      fail(line, "malformed date record " + quoted_excerpt(rec) +
                     ": expected HFDTEDDMMYY or HFDTEDATE:DDMMYY,NN");
    const int year = yy >= 80 ? 1900 + yy : 2000 + yy;
    char iso[32];
    std::snprintf(iso, sizeof iso, "%04d-%02d-%02dT00:00:00Z", year, mm, dd);
    const std::optional<double> t = geo::parse_utc_iso8601(iso);
    if (!t) fail(line, "invalid date in " + quoted_excerpt(rec) + " (day " + std::to_string(dd) +
                           ", month " + std::to_string(mm) + ")");
    day_start_ = *t;
  }

  // DDMMmmm{N|S} (is_lat) or DDDMMmmm{E|W} -> signed degrees, range-checked.
  double parse_coordinate(std::size_t line, std::string_view field, bool is_lat) const {
    const std::size_t deg_digits = is_lat ? 2 : 3;
    const char* name = is_lat ? "latitude" : "longitude";
    const char plus = is_lat ? 'N' : 'E';
    const char minus = is_lat ? 'S' : 'W';
    int deg = 0, min = 0, milli = 0;
    const char hemi = field.back();
    if (!unsigned_digits(field.substr(0, deg_digits), deg) ||
        !unsigned_digits(field.substr(deg_digits, 2), min) ||
        !unsigned_digits(field.substr(deg_digits + 2, 3), milli) ||
        (hemi != plus && hemi != minus))
      fail(line, std::string("malformed B record: ") + name + " " + quoted_excerpt(field) +
                     " is not " + (is_lat ? "DDMMmmm{N|S}" : "DDDMMmmm{E|W}"));
    if (min >= 60)
      fail(line, std::string(name) + " minutes " + std::to_string(min) + " out of range [0, 60)");
    const double value = deg + (min + milli / 1000.0) / 60.0;
    const double limit = is_lat ? 90.0 : 180.0;
    // Latitudes end at the poles. Longitude degrees 180 with minutes (180 00.060'E) are
    // past the antimeridian, the same point as 179 59.940'W: wrapped below. 181 or more
    // is not a recorder counting on but garbage.
    if (is_lat ? value > limit : deg > 180)
      fail(line, std::string(name) + " " + format_number(value) + " deg out of range [-" +
                     format_number(limit) + ", " + format_number(limit) + "]");
    const double signed_value = hemi == minus ? -value : value;
    return is_lat ? signed_value : wrap_lon_deg(signed_value);
  }

  void parse_fix(std::size_t line, std::string_view rec, bool is_last_record) {
    if (rec.size() < kFixLength) {
      const std::string n = std::to_string(rec.size());
      if (is_last_record)
        fail(line, "truncated file: last B record has " + n + " characters, a fix needs 35");
      fail(line, "malformed B record: " + n + " characters, a fix needs at least 35");
    }
    if (!day_start_) fail(line, "B record before the HFDTE date record: missing date");

    int hh = 0, mi = 0, ss = 0;
    if (!unsigned_digits(rec.substr(1, 2), hh) || !unsigned_digits(rec.substr(3, 2), mi) ||
        !unsigned_digits(rec.substr(5, 2), ss))
      fail(line, "malformed B record: time " + quoted_excerpt(rec.substr(1, 6)) + " is not HHMMSS");
    if (hh > 23 || mi > 59 || ss > 59)
      fail(line, "time " + std::string(rec.substr(1, 6)) + " out of range (HHMMSS, 000000-235959)");

    RawFix fix;
    fix.line = line;
    fix.lat_deg = parse_coordinate(line, rec.substr(7, 8), true);
    fix.lon_deg = parse_coordinate(line, rec.substr(15, 9), false);
    const char validity = rec[24];
    if (validity != 'A' && validity != 'V')
      fail(line, "malformed B record: fix validity " + quoted_excerpt(rec.substr(24, 1)) +
                     " is not A or V");
    fix.fix_3d = validity == 'A';
    if (!altitude_field(rec.substr(25, 5), fix.pressure_alt_m))
      fail(line, "malformed B record: pressure altitude " + quoted_excerpt(rec.substr(25, 5)));
    if (!altitude_field(rec.substr(30, 5), fix.gnss_alt_m))
      fail(line, "malformed B record: GNSS altitude " + quoted_excerpt(rec.substr(30, 5)));
    if (!fix.fix_3d && fix.lat_deg == 0.0 && fix.lon_deg == 0.0) return;  // no position yet

    const double sod = hh * 3600.0 + mi * 60.0 + ss;
    if (!fixes_.empty() && last_sod_ - sod > kMidnightWrapMin) ++days_;
    fix.unix_time_s = *day_start_ + days_ * kSecondsPerDay + sod;
    if (!fixes_.empty()) {
      const RawFix& prev = fixes_.back();
      if (fix.unix_time_s == prev.unix_time_s) return;  // repeated fix
      if (fix.unix_time_s < prev.unix_time_s) {
        if (options_.skip_out_of_order) return;
        fail(line, "time goes backwards: " + geo::format_utc_iso8601(fix.unix_time_s) +
                       " after " + geo::format_utc_iso8601(prev.unix_time_s) + " (line " +
                       std::to_string(prev.line) + ")");
      }
    }
    last_sod_ = sod;
    fixes_.push_back(fix);
  }

  // Median (GNSS - pressure) altitude over fixes where both are usable, 0 if none.
  double pressure_offset() const {
    std::vector<double> diffs;
    for (const RawFix& f : fixes_)
      if (f.fix_3d && f.gnss_alt_m != 0 && f.pressure_alt_m != 0)
        diffs.push_back(f.gnss_alt_m - f.pressure_alt_m);
    if (diffs.empty()) return 0.0;
    const auto mid = diffs.begin() + static_cast<std::ptrdiff_t>(diffs.size() / 2);
    std::nth_element(diffs.begin(), mid, diffs.end());
    return *mid;
  }

  PoseTrack build_track() const {
    const double offset = pressure_offset();
    PoseTrack track;
    track.source = source_;
    track.samples.reserve(fixes_.size());
    for (const RawFix& f : fixes_) {
      PoseSample s;
      s.unix_time_s = f.unix_time_s;
      s.position.lat_deg = f.lat_deg;
      s.position.lon_deg = f.lon_deg;
      const bool gnss_ok = f.fix_3d && f.gnss_alt_m != 0;
      s.position.alt_m = gnss_ok ? f.gnss_alt_m : f.pressure_alt_m + offset;
      track.samples.push_back(s);
    }
    derive_attitude_from_track(track.samples, options_.attitude);
    return track;
  }

  std::vector<std::string_view> lines_;
  const std::string& source_;
  const IgcOptions& options_;
  std::optional<double> day_start_;  // unix time of 00:00 UTC on the HFDTE date
  int days_ = 0;                     // midnights crossed since the first fix
  double last_sod_ = 0.0;            // time of day of the last kept fix, s
  std::vector<RawFix> fixes_;
};

}  // namespace

PoseTrack parse_igc(std::string_view text, const std::string& source, const IgcOptions& options) {
  return IgcParser(text, source, options).run();
}

}  // namespace cloudsvc::sim
