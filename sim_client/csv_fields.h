// RFC 4180 field splitting of one CSV line, and quoting for writing.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::sim {

// Fields of one line: separated by commas, optionally quoted ("a,b", "say ""hi""") with no
// line break inside. nullopt when a quoted field is not terminated.
std::optional<std::vector<std::string>> split_csv_fields(std::string_view line);

// s as a CSV field: unchanged unless it holds a comma, quote, CR or LF, then quoted with
// doubled quotes.
std::string csv_quote(std::string_view s);

}  // namespace cloudsvc::sim
