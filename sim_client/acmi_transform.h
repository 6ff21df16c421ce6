// The ACMI "T=" (transform) property: object coordinates.
//
// Four forms, '|'-separated (Tacview ACMI 2.2 reference):
//   3 fields  Lon|Lat|Alt
//   5 fields  Lon|Lat|Alt|U|V
//   6 fields  Lon|Lat|Alt|Roll|Pitch|Yaw
//   9 fields  Lon|Lat|Alt|Roll|Pitch|Yaw|U|V|Heading
// Lon/Lat in degrees, relative to the global ReferenceLongitude/ReferenceLatitude (added by
// the reader); Alt in metres MSL; Roll positive right, Pitch positive nose up, Yaw
// clockwise from true north (degrees). U/V are native flat-world coordinates and Heading
// the yaw in that flat world: both ignored. An empty field means "unchanged since the
// object's previous T=".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace cloudsvc::sim::acmi {

struct Transform {
  int field_count = 0;  // 3, 5, 6 or 9
  // nullopt = empty field (value unchanged); absent in the 3- and 5-field forms too.
  std::optional<double> lon_deg, lat_deg, alt_m;
  std::optional<double> roll_deg, pitch_deg, yaw_deg;
};

// Parses the value of a T= property. Every non-empty field must be a finite number.
// Throws FlightLogError("<source>:<line>: ...") otherwise or on a wrong field count.
Transform parse_transform(std::string_view value, const std::string& source, std::size_t line);

}  // namespace cloudsvc::sim::acmi
