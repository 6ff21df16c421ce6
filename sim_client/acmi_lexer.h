// Tacview ACMI 2.x text: header check and the record stream (logical lines split into
// time frames, object updates with unescaped properties, and object removals).
//
// Syntax (Tacview "Technical Reference - ACMI flight recordings 2.2"; 2.1 is the same for
// what is read here):
//  - UTF-8, an optional byte-order mark; "\n" or "\r\n" line ends.
//  - Line 1 "FileType=text/acmi/tacview", line 2 "FileVersion=2.x" (required).
//  - A line ending in a backslash continues on the next line; the logical line keeps a
//    "\n" there (multi-line texts). Errors name the first physical line.
//  - "//..." comment lines and blank lines are skipped.
//  - "#<seconds>": time frame, seconds since ReferenceTime; must not decrease. Records
//    before the first frame are at time 0.
//  - "<hexid>,Key=Value,Key=Value...": object update (id 0 = global properties). "\,"
//    inside a value is a literal comma; other backslashes are kept as written.
//  - "-<hexid>": object removed.
// A zipped file (.zip.acmi; starts with the ZIP signature "PK\3\4") is rejected with
// "unsupported: zipped ACMI ...; unzip first".
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace cloudsvc::sim::acmi {

struct Property {
  std::string key;
  std::string value;  // with "\," unescaped
};

struct Record {
  enum class Kind { object_update, object_removal };
  Kind kind = Kind::object_update;
  std::size_t line = 0;      // first physical line, 1-based
  double time_s = 0.0;       // current frame time, s since ReferenceTime
  std::uint64_t id = 0;      // object id (0 = global)
  std::vector<Property> properties;  // object_update only
};

// Checks the header and calls on_record for every object update and removal, in file
// order. Throws FlightLogError("<source>:<line>: ...") on malformed lines, a decreasing
// time frame, a truncated continuation, a missing header or a zipped file.
void lex_acmi(std::string_view text, const std::string& source,
              const std::function<void(const Record&)>& on_record);

// "1", "3000102", "0x1A" (optional 0x, 1..16 hex digits) -> id; false otherwise.
bool parse_object_id(std::string_view text, std::uint64_t& id);

// Lower-case hexadecimal, as ACMI writes ids.
std::string format_object_id(std::uint64_t id);

}  // namespace cloudsvc::sim::acmi
