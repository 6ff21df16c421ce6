// UTC time stamps: ISO 8601 parsing and formatting.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cloudsvc::geo {

// Parses an ISO 8601 UTC time: "YYYY-MM-DDTHH:MM[:SS[.fff]]" followed by "Z" or "+00:00"
// (a "-" or "+hh:mm" offset other than zero is converted to UTC). Returns seconds since
// the Unix epoch, or nullopt if the text is malformed or a field is out of range
// (month 13, day 31 in April, hour 24, ...). Years 1900..2199.
std::optional<double> parse_utc_iso8601(std::string_view text);

// Seconds since the Unix epoch of a UTC calendar date and time, or nullopt when a field is
// out of range (the rules of parse_utc_iso8601: years 1900..2199, no hour 24 or second 60).
std::optional<double> utc_from_civil(int year, int month, int day, int hour, int minute, int second);

// Formats seconds since the Unix epoch as "YYYY-MM-DDTHH:MM:SSZ" (rounded to 1 s).
std::string format_utc_iso8601(double unix_time_s);

}  // namespace cloudsvc::geo
