// The extension of a file name, which decides how weather files are read (GRIB2, METAR).
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

namespace cloudsvc::weather {

// The text after the last '.' of the path's file name, in lower case ("grib2" for
// "a/B.GRIB2"); empty when the file name has no '.'.
inline std::string lowercase_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace cloudsvc::weather
