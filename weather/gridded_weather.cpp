// Forecast steps sampled in space and time (gridded_weather.h).
#include "weather/gridded_weather.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "weather/standard_atmosphere.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {

namespace {

bool given(double v) { return std::isfinite(v); }

// Full-level pressure of hybrid level k (1-based) from the vertical coordinate parameters
// pv = [a_0 .. a_N, b_0 .. b_N] of the half levels (Pa, dimensionless): the mean of the
// half-level pressures a + b p_s around it (ECMWF IFS Documentation, Part III, eq. 2.11).
double hybrid_level_pressure(const std::vector<double>& pv, double level, double surface_Pa) {
  const std::size_t half = pv.size() / 2;
  const auto k = static_cast<std::size_t>(std::lround(level));
  if (k < 1 || k >= half) return std::nan("");
  const double upper = pv[k - 1] + pv[half + k - 1] * surface_Pa;
  const double lower = pv[k] + pv[half + k] * surface_Pa;
  return 0.5 * (upper + lower);
}

}  // namespace

GriddedWeather GriddedWeather::load_grib(const std::vector<std::string>& paths) {
  std::vector<GribCloudMessage> all;
  std::string name;
  for (const std::string& path : paths) {
    GribReadResult r = read_grib_cloud_fields(path);
    for (GribCloudMessage& m : r.clouds) all.push_back(std::move(m));
    name += (name.empty() ? "" : ", ") + path;
  }
  if (paths.empty()) throw WeatherFileError("no GRIB files given");
  return from_messages(std::move(all), name);
}

GriddedWeather GriddedWeather::from_messages(std::vector<GribCloudMessage> messages, std::string name) {
  GriddedWeather w;
  w.name_ = std::move(name);
  std::map<double, Step> by_time;
  for (GribCloudMessage& m : messages) {
    Step& step = by_time[m.valid_utc_s];
    step.valid_utc_s = m.valid_utc_s;
    step.fields.push_back(std::move(m));
  }
  for (auto& [t, step] : by_time) w.steps_.push_back(std::move(step));
  if (w.steps_.empty()) throw WeatherFileError(w.name_ + ": no cloud fields");
  // The ground's height (time-invariant): the first orography field of any step.
  for (const Step& s : w.steps_)
    for (const GribCloudMessage& m : s.fields)
      if (!w.orography_ && m.role.quantity == CloudQuantity::Orography) w.orography_ = m;
  return w;
}

std::vector<double> GriddedWeather::valid_times() const {
  std::vector<double> t;
  for (const Step& s : steps_) t.push_back(s.valid_utc_s);
  return t;
}

CloudColumn GriddedWeather::column_in_step(const Step& step, double lat, double lon) const {
  CloudColumn column;
  const double ground_m = orography_ ? orography_->field.at(lat, lon) : std::nan("");
  column.ground_m = ground_m;
  const auto above_sea = [&](const GribCloudMessage& m, double v) {
    return m.above_ground && given(ground_m) ? v + ground_m : v;
  };
  std::vector<ProfileSample> profile;
  for (const GribCloudMessage& m : step.fields) {
    const CloudFieldRole& role = m.role;
    if (role.quantity == CloudQuantity::Orography) continue;
    const double v = m.field.at(lat, lon);
    if (role.band == CloudBand::Profile) {
      double altitude = std::nan("");
      switch (role.level) {
        case ProfileLevel::Pressure_Pa: altitude = standard_pressure_altitude_m(m.level_value); break;
        case ProfileLevel::AboveSea_m: altitude = m.level_value; break;
        case ProfileLevel::AboveGround_m: altitude = m.level_value + (given(ground_m) ? ground_m : 0.0); break;
        case ProfileLevel::Hybrid:
          altitude = standard_pressure_altitude_m(hybrid_level_pressure(m.pv, m.level_value, kSeaLevelPressure_Pa));
          break;
        case ProfileLevel::None: break;
      }
      profile.push_back({altitude, v});
      continue;
    }
    BandValues& band = column[role.band];
    switch (role.quantity) {
      case CloudQuantity::Cover: band.cover = v; break;
      case CloudQuantity::Base: band.base_m = above_sea(m, v); break;
      case CloudQuantity::Top: band.top_m = above_sea(m, v); break;
      case CloudQuantity::Orography: break;
    }
  }
  fill_bands_from_profile(column, std::move(profile));
  return column;
}

CloudColumn GriddedWeather::column_at(double lat, double lon, double utc_s) const {
  if (!given(utc_s) || utc_s <= steps_.front().valid_utc_s) return column_in_step(steps_.front(), lat, lon);
  if (utc_s >= steps_.back().valid_utc_s) return column_in_step(steps_.back(), lat, lon);
  const auto after = std::upper_bound(steps_.begin(), steps_.end(), utc_s,
                                      [](double t, const Step& s) { return t < s.valid_utc_s; });
  const Step& b = *after;
  const Step& a = *(after - 1);
  const double w = (utc_s - a.valid_utc_s) / (b.valid_utc_s - a.valid_utc_s);
  return blend_columns(column_in_step(a, lat, lon), column_in_step(b, lat, lon), w);
}

}  // namespace cloudsvc::weather
