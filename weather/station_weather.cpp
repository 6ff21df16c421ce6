// METAR reports -> cloud bands over aerodromes, blended in space and time (station_weather.h).
#include "weather/station_weather.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "weather/sphere_geometry.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {

namespace {

constexpr double kFoot_m = 0.3048;
constexpr double kLowTop_m = 2000.0, kMiddleTop_m = 6000.0;  // etage limits above the ground

bool given(double v) { return std::isfinite(v); }

// Widens a band with one group: cover the largest, base the lowest, top the highest.
void widen(BandValues& b, double cover, double base_m, double top_m) {
  b.cover = given(b.cover) ? std::max(b.cover, cover) : cover;
  b.base_m = given(b.base_m) ? std::min(b.base_m, base_m) : base_m;
  b.top_m = given(b.top_m) ? std::max(b.top_m, top_m) : top_m;
}

// A report's visibility to blend: the drawn one, the clear air for "or more", NaN when the
// report gives none.
double blended_visibility(const MetarReport& r) {
  if (r.nil || !given(r.visibility_m)) return std::numeric_limits<double>::quiet_NaN();
  return drawn_visibility(r).value_or(kClearAirVisibility_m);
}

}  // namespace

CloudColumn column_of_report(const MetarReport& report, const Aerodrome& aerodrome) {
  CloudColumn c;
  c.ground_m = aerodrome.elevation_m;
  if (report.nil) return c;
  const double e = aerodrome.elevation_m;
  bool said = report.clear;
  for (const SkyGroup& g : report.sky) {
    const double cover = sky_cover(g.amount);
    if (g.amount == SkyGroup::Amount::Obscured) {  // fog: from the ground to the vertical visibility
      const double vv = given(g.height_ft) ? g.height_ft * kFoot_m : 100.0 * kFoot_m;
      widen(c[CloudBand::Low], cover, e, e + vv);
      said = true;
      continue;
    }
    if (!given(g.height_ft)) continue;  // "///": height unknown
    said = true;
    const double h = g.height_ft * kFoot_m, base = e + h;
    switch (g.cloud) {
      case SkyGroup::Cloud::Cumulonimbus:
        widen(c[CloudBand::Convective], cover, base,
              std::max(base + kToweringCumulusDepth_m, cloud_type_traits(CloudType::Cumulonimbus).default_top_m));
        continue;
      case SkyGroup::Cloud::ToweringCumulus:
        widen(c[CloudBand::Convective], cover, base,
              std::max(base + kLeastBandThickness_m, std::min(base + kToweringCumulusDepth_m, kDeepConvectionTop_m - 1.0)));
        continue;
      case SkyGroup::Cloud::Any: break;
    }
    const int band = h < kLowTop_m ? 0 : h < kMiddleTop_m ? 1 : 2;
    const CloudBand bands[3] = {CloudBand::Low, CloudBand::Middle, CloudBand::High};
    widen(c[bands[band]], cover, base, base + kDeckDepth_m[band]);
  }
  if (!said) return c;  // no sky information
  for (CloudBand b : {CloudBand::Low, CloudBand::Middle, CloudBand::High, CloudBand::Convective})
    if (!given(c[b].cover)) c[b].cover = 0.0;
  return c;
}

StationWeather StationWeather::from_reports(const std::vector<MetarReport>& reports, const std::string& path) {
  StationWeather w;
  w.name_ = path;
  std::map<std::string, Station> by_code;
  for (const MetarReport& r : reports) {
    const Aerodrome* a = find_aerodrome(r.station);
    if (!a)
      throw WeatherFileError(path + ": line " + std::to_string(r.line) + ": station '" + r.station +
                             "' is not in the aerodrome table (" + std::to_string(aerodrome_count()) +
                             " medium and large aerodromes of OurAirports, docs/WEATHER.md)");
    Station& s = by_code[r.station];
    s.aerodrome = *a;
    s.unit = unit_vector(a->lat_deg, a->lon_deg);
    s.observations.push_back({r.utc_s, column_of_report(r, *a), blended_visibility(r), r.speci});
  }
  for (auto& [code, s] : by_code) {
    // Ascending time; of two reports at one time a SPECI (correcting the METAR) wins wherever
    // it stands in the file (newest-first listings put it before the METAR), else the later.
    std::stable_sort(s.observations.begin(), s.observations.end(),
                     [](const Observation& a, const Observation& b) { return a.utc_s < b.utc_s; });
    std::vector<Observation> unique;
    for (const Observation& o : s.observations) {
      if (unique.empty() || unique.back().utc_s != o.utc_s) unique.push_back(o);
      else if (replaces(o, unique.back())) unique.back() = o;
    }
    s.observations = std::move(unique);
    w.stations_.push_back(std::move(s));
  }
  return w;
}

void StationWeather::merge(const StationWeather& other) {
  for (const Station& o : other.stations_) {
    auto it = std::find_if(stations_.begin(), stations_.end(), [&](const Station& s) { return s.aerodrome.icao == o.aerodrome.icao; });
    if (it == stations_.end()) {
      stations_.push_back(o);
      continue;
    }
    for (const Observation& ob : o.observations) {
      auto at = std::lower_bound(it->observations.begin(), it->observations.end(), ob.utc_s,
                                 [](const Observation& a, double t) { return a.utc_s < t; });
      if (at != it->observations.end() && at->utc_s == ob.utc_s) {
        if (replaces(ob, *at)) *at = ob;  // the later file's, unless it would undo a SPECI
      }
      else it->observations.insert(at, ob);
    }
  }
  name_ += ", " + other.name_;
}

std::vector<double> StationWeather::valid_times() const {
  std::vector<double> t;
  for (const Station& s : stations_)
    for (const Observation& o : s.observations) t.push_back(o.utc_s);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

StationWeather::Bracket StationWeather::bracket(const Station& s, double utc_s) {
  const std::vector<Observation>& o = s.observations;
  if (!given(utc_s) || utc_s <= o.front().utc_s) return {o.front(), o.front(), 0.0};
  if (utc_s >= o.back().utc_s) return {o.back(), o.back(), 0.0};
  const auto after = std::upper_bound(o.begin(), o.end(), utc_s, [](double t, const Observation& x) { return t < x.utc_s; });
  const Observation& a = *(after - 1);
  const Observation& b = *after;
  return {a, b, (utc_s - a.utc_s) / (b.utc_s - a.utc_s)};
}

double StationWeather::station_weight(const std::array<double, 3>& p, const Station& s) {
  const double d = std::max(kMeanEarthRadius_m * arc_between(p, s.unit), 1.0);
  if (d >= kStationReach_m) return 0.0;
  const double r = (kStationReach_m - d) / (kStationReach_m * d);
  return r * r;
}

CloudColumn StationWeather::station_column(const Station& s, double utc_s) const {
  const Bracket t = bracket(s, utc_s);
  return &t.a == &t.b ? t.a.column : blend_columns(t.a.column, t.b.column, t.w);
}

double StationWeather::station_visibility(const Station& s, double utc_s) const {
  const Bracket t = bracket(s, utc_s);
  const double a = t.a.visibility_m, b = t.b.visibility_m;
  if (!given(a) || !given(b)) return given(a) ? a : b;  // given in one of them: it holds
  return 1.0 / ((1.0 - t.w) / a + t.w / b);  // extinction blended linearly
}

std::optional<double> StationWeather::visibility_at(double lat_deg, double lon_deg, double utc_s) const {
  const std::array<double, 3> p = unit_vector(lat_deg, lon_deg);
  double weights = 0.0, extinction = 0.0;  // sums of w and w / V
  for (const Station& s : stations_) {
    const double w = station_weight(p, s);
    if (w <= 0.0) continue;
    const double v = station_visibility(s, utc_s);
    if (!given(v)) continue;
    weights += w;
    extinction += w / v;
  }
  if (weights <= 0.0) return std::nullopt;  // no aerodrome within reach reports a visibility
  const double v = weights / extinction;
  // Within 1 % of the clear air's extinction (a clear aerodrome's own, a hazy one's far off):
  // the clear air, unset.
  if (v >= kClearAirVisibility_m / 1.01) return std::nullopt;
  return std::max(v, kMinVisibility_m);
}

CloudColumn StationWeather::column_at(double lat_deg, double lon_deg, double utc_s) const {
  const std::array<double, 3> p = unit_vector(lat_deg, lon_deg);
  ColumnAverage blend;
  for (const Station& s : stations_) {
    const double w = station_weight(p, s);
    if (w > 0.0) blend.add(station_column(s, utc_s), w);
  }
  return blend.result();
}

}  // namespace cloudsvc::weather
