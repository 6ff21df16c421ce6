// Strict ISO 8601 UTC time stamps <-> seconds since the Unix epoch (leap seconds
// ignored, as in POSIX time). Calendar arithmetic is the proleptic Gregorian
// days-from-civil / civil-from-days mapping (400-year era decomposition, cf. H. Hinnant,
// "chrono-compatible low-level date algorithms"), so nothing depends on the C library's
// time zone, locale or timegm.
#include "geodesy/utc_time.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace cloudsvc::geo {

namespace {

constexpr int kMinYear = 1900;
constexpr int kMaxYear = 2199;
constexpr std::int64_t kSecondsPerDay = 86400;

bool is_leap(int y) { return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0; }

int days_in_month(int y, int m) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return (m == 2 && is_leap(y)) ? 29 : kDays[m - 1];
}

// Days since 1970-01-01 of the proleptic Gregorian date y-m-d (m 1..12, d 1..31).
// Years are shifted to start in March so the leap day is the last day of a year.
std::int64_t days_from_civil(std::int64_t y, int m, int d) {
  y -= (m <= 2) ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t yoe = y - era * 400;                            // [0, 399]
  const int mp = (m + 9) % 12;                                       // March = 0
  const std::int64_t doy = (153 * mp + 2) / 5 + d - 1;               // [0, 365]
  const std::int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;    // [0, 146096]
  return era * 146097 + doe - 719468;  // 719468 = days from 0000-03-01 to 1970-01-01
}

struct Civil {
  std::int64_t y;
  int m;
  int d;
};

// Inverse of days_from_civil.
Civil civil_from_days(std::int64_t z) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t doe = z - era * 146097;                                   // [0, 146096]
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;  // [0, 399]
  const std::int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);            // [0, 365]
  const std::int64_t mp = (5 * doy + 2) / 153;                                 // March = 0
  const int d = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  const int m = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  return {era * 400 + yoe + (m <= 2 ? 1 : 0), m, d};
}

// Cursor over the text; every reader fails (returns false) rather than guessing.
struct Reader {
  std::string_view s;
  std::size_t i = 0;

  bool done() const { return i == s.size(); }
  bool peek(char c) const { return i < s.size() && s[i] == c; }
  bool expect(char c) {
    if (!peek(c)) return false;
    ++i;
    return true;
  }
  // Exactly n ASCII digits.
  bool digits(int n, int& out) {
    if (s.size() - i < static_cast<std::size_t>(n)) return false;
    int v = 0;
    for (int k = 0; k < n; ++k) {
      const char c = s[i + static_cast<std::size_t>(k)];
      if (c < '0' || c > '9') return false;
      v = v * 10 + (c - '0');
    }
    i += static_cast<std::size_t>(n);
    out = v;
    return true;
  }
  // One or more digits after a decimal point, as a fraction in [0, 1).
  bool fraction(double& out) {
    double f = 0.0, scale = 0.1;
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
      f += (s[i] - '0') * scale;
      scale *= 0.1;
      ++i;
    }
    out = f;
    return i > start;
  }
};

}  // namespace

std::optional<double> parse_utc_iso8601(std::string_view text) {
  Reader r{text};
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  double frac = 0.0;
  if (!r.digits(4, year) || !r.expect('-') || !r.digits(2, month) || !r.expect('-') ||
      !r.digits(2, day) || !r.expect('T') || !r.digits(2, hour) || !r.expect(':') ||
      !r.digits(2, minute))
    return std::nullopt;
  if (r.expect(':')) {
    if (!r.digits(2, second)) return std::nullopt;
    if (r.expect('.') && !r.fraction(frac)) return std::nullopt;
  }
  // Zone designator: "Z" or "+hh:mm" / "-hh:mm" (local = UTC + offset).
  int offset_s = 0;
  if (r.expect('Z')) {
  } else if (r.peek('+') || r.peek('-')) {
    const int sign = r.peek('-') ? -1 : 1;
    ++r.i;
    int oh = 0, om = 0;
    if (!r.digits(2, oh) || !r.expect(':') || !r.digits(2, om)) return std::nullopt;
    if (oh > 23 || om > 59) return std::nullopt;
    offset_s = sign * (oh * 3600 + om * 60);
  } else {
    return std::nullopt;  // a time without a zone is local time: refuse it
  }
  if (!r.done()) return std::nullopt;

  const std::optional<double> utc = utc_from_civil(year, month, day, hour, minute, second);
  if (!utc) return std::nullopt;
  return *utc - static_cast<double>(offset_s) + frac;
}

std::optional<double> utc_from_civil(int year, int month, int day, int hour, int minute, int second) {
  if (year < kMinYear || year > kMaxYear || month < 1 || month > 12 || day < 1 ||
      day > days_in_month(year, month))
    return std::nullopt;
  // Hour 24 (end of day) and leap second 60 are not accepted: POSIX time has neither.
  if (hour < 0 || minute < 0 || second < 0 || hour > 23 || minute > 59 || second > 59) return std::nullopt;
  const std::int64_t days = days_from_civil(year, month, day);
  return static_cast<double>(days * kSecondsPerDay + hour * 3600 + minute * 60 + second);
}

std::string format_utc_iso8601(double unix_time_s) {
  // Years 0000..9999 fit the fixed-width format; anything else (or NaN/Inf) gives "".
  constexpr double kLimit = 253402300800.0;  // 10000-01-01T00:00:00Z
  constexpr double kFirst = -62167219200.0;  // 0000-01-01T00:00:00Z
  if (!std::isfinite(unix_time_s)) return {};
  const double rounded = std::floor(unix_time_s + 0.5);
  if (rounded < kFirst || rounded >= kLimit) return {};
  const auto t = static_cast<std::int64_t>(rounded);
  std::int64_t days = t / kSecondsPerDay;
  std::int64_t sod = t % kSecondsPerDay;
  if (sod < 0) {  // floor division for times before 1970
    sod += kSecondsPerDay;
    --days;
  }
  const Civil c = civil_from_days(days);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02dZ", static_cast<int>(c.y), c.m,
                c.d, static_cast<int>(sod / 3600), static_cast<int>(sod / 60 % 60),
                static_cast<int>(sod % 60));
  return buf;
}

}  // namespace cloudsvc::geo
