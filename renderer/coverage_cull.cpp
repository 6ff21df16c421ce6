#include "renderer/coverage_cull.h"

#include "renderer/model/scene_constants.h"

#include <algorithm>
#include <cmath>

namespace cloudsvc {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kLightMarchM = model::kLightMarchReach_m;  // the longest light march
}  // namespace

float max_coverage_in_cap(const weather::WeatherMap& map, double lat_deg, double lon_deg, double cap_rad) {
  if (map.width <= 0 || map.height <= 0 || map.rgba.empty()) return 0.5f;  // neutral, as sample() gives
  const double W = map.width, H = map.height;
  const double texel_lat = 180.0 / H, texel_lon = 360.0 / W;
  const double a_deg = cap_rad * 180.0 / kPi;
  const double lat0 = lat_deg - a_deg - texel_lat, lat1 = lat_deg + a_deg + texel_lat;
  // rows whose texel centres lie within the widened latitude range (row j centred at
  // -90 + (j + 0.5) 180 / H), plus the neighbour the bilinear footprint reaches
  const int j0 = std::max(0, static_cast<int>(std::floor((lat0 + 90.0) / texel_lat - 0.5)) - 1);
  const int j1 = std::min(map.height - 1, static_cast<int>(std::ceil((lat1 + 90.0) / texel_lat - 0.5)) + 1);
  bool all_lon = lat0 <= -90.0 || lat1 >= 90.0 || cap_rad >= 0.5 * kPi;
  double half_lon_deg = 180.0;
  if (!all_lon) {
    const double s = std::sin(cap_rad) / std::cos(lat_deg * kPi / 180.0);  // spherical cap's longitude extent
    if (s >= 1.0) all_lon = true;
    else half_lon_deg = std::asin(s) * 180.0 / kPi + texel_lon;
  }
  int i0 = 0, i1 = map.width - 1;
  if (!all_lon) {
    i0 = static_cast<int>(std::floor((lon_deg - half_lon_deg + 180.0) / texel_lon - 0.5)) - 1;
    i1 = static_cast<int>(std::ceil((lon_deg + half_lon_deg + 180.0) / texel_lon - 0.5)) + 1;
    if (i1 - i0 + 1 >= map.width) { i0 = 0; i1 = map.width - 1; }
  }
  float m = 0.0f;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const int wi = ((i % map.width) + map.width) % map.width;  // wraps across the antimeridian
      m = std::max(m, map.coverage_bound(static_cast<size_t>(j) * map.width + wi));  // non-finite: 1
    }
  return m;
}

double cloud_influence_cap_rad(double R_m, double reach_m) {
  // the arc to a point at chord distance d exceeds d by < 0.1 % at 1000 km: 1 % margin
  return std::min((1.01 * reach_m + kLightMarchM) / R_m, kPi);
}

}  // namespace cloudsvc
