// The embedded aerodrome table (aerodrome_table.h).
#include "weather/aerodrome_table.h"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <vector>

namespace cloudsvc::embedded {
extern const unsigned char aerodrome_table[];
extern const std::size_t aerodrome_table_size;
}  // namespace cloudsvc::embedded

namespace cloudsvc::weather {

namespace {

constexpr double kFoot_m = 0.3048;  // international foot

double number(std::string_view field) {
  double v = 0.0;
  const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (r.ec != std::errc() || r.ptr != field.data() + field.size())
    throw std::logic_error("aerodrome table: bad number '" + std::string(field) + "'");
  return v;
}

// The table's rows "ICAO,lat,lon,elevation_ft", sorted by code; '#' lines and the header skipped.
std::vector<Aerodrome> parse_table() {
  const std::string_view text(reinterpret_cast<const char*>(embedded::aerodrome_table), embedded::aerodrome_table_size);
  std::vector<Aerodrome> rows;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (line.empty() || line[0] == '#' || line.rfind("icao,", 0) == 0) continue;
    std::string_view f[4];
    std::size_t at = 0;
    for (int k = 0; k < 4; ++k) {
      const std::size_t comma = k < 3 ? line.find(',', at) : line.size();
      if (comma == std::string_view::npos) throw std::logic_error("aerodrome table: short row '" + std::string(line) + "'");
      f[k] = line.substr(at, comma - at);
      at = comma + 1;
    }
    rows.push_back({std::string(f[0]), number(f[1]), number(f[2]), number(f[3]) * kFoot_m});
  }
  std::sort(rows.begin(), rows.end(), [](const Aerodrome& a, const Aerodrome& b) { return a.icao < b.icao; });
  return rows;
}

const std::vector<Aerodrome>& table() {
  static const std::vector<Aerodrome> rows = parse_table();
  return rows;
}

}  // namespace

const Aerodrome* find_aerodrome(std::string_view icao) {
  const std::vector<Aerodrome>& rows = table();
  const auto it = std::lower_bound(rows.begin(), rows.end(), icao,
                                   [](const Aerodrome& a, std::string_view code) { return a.icao < code; });
  return it != rows.end() && it->icao == icao ? &*it : nullptr;
}

std::size_t aerodrome_count() { return table().size(); }

}  // namespace cloudsvc::weather
