// The checks a host's packet must pass before the IG uses it (cigi_packets.h): every float
// finite, every value within the standard's range or the IG's (docs/CIGI.md, "Bad
// datagrams"). Each returns the first problem as "<field> <value> out of range [lo, hi]"
// (or "... is nan"), empty when the packet is usable.
#pragma once

#include <string>

#include "protocol/cigi/cigi_packets.h"

namespace cloudsvc::cigi {

std::string check(const IgControl& p);
std::string check(const EntityControl& p);  // the ownship's; other entities are not checked
std::string check(const ViewControl& p);
std::string check(const ViewDefinition& p);
std::string check(const CelestialSphereControl& p);
std::string check(const AtmosphereControl& p);
std::string check(const EnvironmentalRegionControl& p);
std::string check(const WeatherControl& p);

// Altitudes the IG accepts, m above mean sea level (as the service's own protocol's Pose).
inline constexpr double kMinAltitude_m = -500.0, kMaxAltitude_m = 100000.0;
// Largest view offset from the ownship, m, and the farthest far plane, m.
inline constexpr double kMaxViewOffset_m = 10000.0;
// Largest half-angle of a view from its axis, degrees (a view spans less than 180°).
inline constexpr double kMaxHalfAngle_deg = 85.0;
// Cloud layers: base and top within these altitudes, m above mean sea level.
inline constexpr double kMinLayerAltitude_m = -500.0, kMaxLayerAltitude_m = 20000.0;

}  // namespace cloudsvc::cigi
