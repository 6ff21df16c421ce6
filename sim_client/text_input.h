// Text helpers shared by the flight-log readers: whole-file input, line splitting and
// locale-independent number parsing.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::sim {

// The whole file as bytes. Throws FlightLogError(path, 0, "cannot open ...") on failure.
std::string read_text_file(const std::string& path);

// Physical lines of a text: a leading UTF-8 byte-order mark is dropped, lines end at "\n"
// with an optional preceding "\r". Line k (1-based) is element k - 1. A final line without
// a newline is kept; a text ending in "\n" has no empty last element.
std::vector<std::string_view> split_lines(std::string_view text);

// Without leading/trailing spaces and tabs.
std::string_view trim(std::string_view s);

// The whole of s (after trim) as a decimal floating-point number ("12", "-3.5", "+1e3").
// Infinity and NaN spellings parse and are returned as such so that callers can report
// them as non-finite rather than as malformed. nullopt for anything else (including "").
std::optional<double> parse_number(std::string_view s);

// ASCII case-insensitive equality (bytes >= 0x80 compare exactly).
bool iequals(std::string_view a, std::string_view b);
std::string to_lower_ascii(std::string_view s);

// v for an error message: shortest of "%.10g" ("95.1", "1e+06", "nan", "inf").
std::string format_number(double v);

// s for an error message: at most 48 bytes, quoted, non-printable bytes as '?'.
std::string quoted_excerpt(std::string_view s);

}  // namespace cloudsvc::sim
