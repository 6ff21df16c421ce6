// The aerodromes METAR reports come from: ICAO code, position and field elevation of every
// medium and large aerodrome of OurAirports (public domain; weather/data/aerodromes.csv,
// embedded in the program at build time; regenerate with scripts/make-aerodrome-table.sh).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cloudsvc::weather {

struct Aerodrome {
  std::string icao;
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  double elevation_m = 0.0;  // field elevation above mean sea level (the table's feet x 0.3048)
};

// The aerodrome with this ICAO code (upper case), or nullptr.
const Aerodrome* find_aerodrome(std::string_view icao);

// Number of aerodromes in the table.
std::size_t aerodrome_count();

}  // namespace cloudsvc::weather
