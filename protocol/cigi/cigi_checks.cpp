// Field checks of host packets (cigi_checks.h).
#include "protocol/cigi/cigi_checks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "geodesy/utc_time.h"

namespace cloudsvc::cigi {
namespace {

// Shortest text that reads back to v, without an exponent for everyday magnitudes
// ("1000000", "0.25", "1e+30", "nan").
std::string num(double v) {
  char buf[64];
  const bool everyday = std::abs(v) >= 1e-6 && std::abs(v) < 1e15;
  const auto r = everyday ? std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed)
                          : std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// "<field> <v> out of range [lo, hi]" or "<field> is nan", empty when v is in [lo, hi].
std::string in_range(std::string_view field, double v, double lo, double hi) {
  if (std::isnan(v) || std::isinf(v)) return std::string(field) + " is " + num(v) + " (must be finite)";
  if (v < lo || v > hi) return std::string(field) + " " + num(v) + " out of range [" + num(lo) + ", " + num(hi) + "]";
  return {};
}

constexpr double kHuge = 1.0e9;  // "any finite value" for fields the IG only stores

#define CHECK(expr)                                     \
  do {                                                  \
    if (std::string p_ = (expr); !p_.empty()) return p_; \
  } while (false)

}  // namespace

std::string check(const IgControl& p) {
  CHECK(in_range("ig_mode", static_cast<double>(p.mode), 0, 2));
  return {};
}

std::string check(const EntityControl& p) {
  CHECK(in_range("state", p.state, 0, 2));
  CHECK(in_range("roll_deg", p.roll_deg, -180.0, 180.0));
  CHECK(in_range("pitch_deg", p.pitch_deg, -90.0, 90.0));
  CHECK(in_range("yaw_deg", p.yaw_deg, -360.0, 360.0));
  if (p.attached) return "attached to entity " + std::to_string(p.parent_id) + " (the ownship has no parent)";
  CHECK(in_range("lat_deg", p.lat_deg, -90.0, 90.0));
  CHECK(in_range("lon_deg", p.lon_deg, -180.0, 360.0));
  CHECK(in_range("alt_m", p.alt_m, kMinAltitude_m, kMaxAltitude_m));
  return {};
}

std::string check(const ViewControl& p) {
  if (p.entity_id != 0) return "entity_id " + std::to_string(p.entity_id) + ": views are attached to the ownship (0)";
  CHECK(in_range("x_m", p.x_m, -kMaxViewOffset_m, kMaxViewOffset_m));
  CHECK(in_range("y_m", p.y_m, -kMaxViewOffset_m, kMaxViewOffset_m));
  CHECK(in_range("z_m", p.z_m, -kMaxViewOffset_m, kMaxViewOffset_m));
  CHECK(in_range("roll_deg", p.roll_deg, -180.0, 180.0));
  CHECK(in_range("pitch_deg", p.pitch_deg, -90.0, 90.0));
  CHECK(in_range("yaw_deg", p.yaw_deg, -360.0, 360.0));
  return {};
}

std::string check(const ViewDefinition& p) {
  if (p.orthographic) return "orthographic projection (the IG draws perspective views)";
  using namespace definition_enable;
  if (p.enable & kNear) CHECK(in_range("near_m", p.near_m, 1e-3, kHuge));
  if (p.enable & kFar) CHECK(in_range("far_m", p.far_m, 1e-3, kHuge));
  if ((p.enable & kNear) && (p.enable & kFar) && !(p.far_m > p.near_m))
    return "far_m " + num(p.far_m) + " not beyond near_m " + num(p.near_m);
  if (p.enable & kLeft) CHECK(in_range("left_deg", p.left_deg, -kMaxHalfAngle_deg, kMaxHalfAngle_deg));
  if (p.enable & kRight) CHECK(in_range("right_deg", p.right_deg, -kMaxHalfAngle_deg, kMaxHalfAngle_deg));
  if (p.enable & kTop) CHECK(in_range("top_deg", p.top_deg, -kMaxHalfAngle_deg, kMaxHalfAngle_deg));
  if (p.enable & kBottom) CHECK(in_range("bottom_deg", p.bottom_deg, -kMaxHalfAngle_deg, kMaxHalfAngle_deg));
  if ((p.enable & kLeft) && (p.enable & kRight) && !(p.right_deg > p.left_deg))
    return "right_deg " + num(p.right_deg) + " not right of left_deg " + num(p.left_deg);
  if ((p.enable & kTop) && (p.enable & kBottom) && !(p.top_deg > p.bottom_deg))
    return "top_deg " + num(p.top_deg) + " not above bottom_deg " + num(p.bottom_deg);
  return {};
}

std::string check(const CelestialSphereControl& p) {
  CHECK(in_range("hour", p.hour, 0, 23));
  CHECK(in_range("minute", p.minute, 0, 59));
  CHECK(in_range("star_intensity_pct", p.star_intensity_pct, 0.0, 100.0));
  if (!p.date_valid) return {};
  const int month = static_cast<int>(p.date / 1000000), day = static_cast<int>(p.date / 10000 % 100),
            year = static_cast<int>(p.date % 10000);
  if (!geo::utc_from_civil(year, month, day, p.hour, p.minute, 0))
    return "date " + std::to_string(p.date) + " is not a date MMDDYYYY in 1900..2199";
  return {};
}

std::string check(const AtmosphereControl& p) {
  CHECK(in_range("humidity_pct", p.humidity_pct, 0, 100));
  CHECK(in_range("air_temperature_c", p.air_temperature_c, -100.0, 100.0));
  CHECK(in_range("visibility_m", p.visibility_m, 0.0, kHuge));
  CHECK(in_range("wind_horizontal_mps", p.wind_horizontal_mps, 0.0, 150.0));
  CHECK(in_range("wind_vertical_mps", p.wind_vertical_mps, -150.0, 150.0));
  CHECK(in_range("wind_direction_deg", p.wind_direction_deg, -360.0, 360.0));
  CHECK(in_range("pressure_hpa", p.pressure_hpa, 0.0, 2000.0));
  return {};
}

std::string check(const EnvironmentalRegionControl& p) {
  CHECK(in_range("state", p.state, 0, 2));
  CHECK(in_range("lat_deg", p.lat_deg, -90.0, 90.0));
  CHECK(in_range("lon_deg", p.lon_deg, -180.0, 360.0));
  CHECK(in_range("size_x_m", p.size_x_m, 0.0, 2.0e7));
  CHECK(in_range("size_y_m", p.size_y_m, 0.0, 2.0e7));
  CHECK(in_range("corner_radius_m", p.corner_radius_m, 0.0, 0.5 * std::min(p.size_x_m, p.size_y_m)));
  CHECK(in_range("rotation_deg", p.rotation_deg, -360.0, 360.0));
  CHECK(in_range("transition_perimeter_m", p.transition_perimeter_m, 0.0, 2.0e7));
  return {};
}

std::string check(const WeatherControl& p) {
  CHECK(in_range("humidity_pct", p.humidity_pct, 0, 100));
  CHECK(in_range("cloud_type", p.cloud_type, 0, 10));  // 11..15 are IG-defined: this IG has none
  CHECK(in_range("scope", static_cast<double>(p.scope), 0, 2));
  CHECK(in_range("severity", p.severity, 0, 5));
  CHECK(in_range("air_temperature_c", p.air_temperature_c, -100.0, 100.0));
  CHECK(in_range("visibility_m", p.visibility_m, 0.0, kHuge));
  CHECK(in_range("scud_frequency_pct", p.scud_frequency_pct, 0.0, 100.0));
  CHECK(in_range("coverage_pct", p.coverage_pct, 0.0, 100.0));
  CHECK(in_range("base_elevation_m", p.base_elevation_m, kMinLayerAltitude_m, kMaxLayerAltitude_m));
  CHECK(in_range("thickness_m", p.thickness_m, 0.0, kMaxLayerAltitude_m - p.base_elevation_m));
  CHECK(in_range("transition_band_m", p.transition_band_m, 0.0, kMaxLayerAltitude_m));
  CHECK(in_range("wind_horizontal_mps", p.wind_horizontal_mps, 0.0, 150.0));
  CHECK(in_range("wind_vertical_mps", p.wind_vertical_mps, -150.0, 150.0));
  CHECK(in_range("wind_direction_deg", p.wind_direction_deg, -360.0, 360.0));
  CHECK(in_range("pressure_hpa", p.pressure_hpa, 0.0, 2000.0));
  CHECK(in_range("aerosol_gpm3", p.aerosol_gpm3, 0.0, kHuge));
  return {};
}

#undef CHECK

}  // namespace cloudsvc::cigi
