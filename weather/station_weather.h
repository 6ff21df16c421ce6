// Weather from METAR / SPECI reports (metar.h) at their aerodromes (aerodrome_table.h):
// each report's sky groups become cloud bands over its aerodrome, and the bands are blended
// between aerodromes and between each aerodrome's reports in time.
//
// Bands of a report, with h a group's height above the aerodrome and e the aerodrome's
// elevation (base = e + h):
//   - CB -> convective, top at least the cumulonimbus type's default top (deep convection);
//     TCU -> convective, top kToweringCumulusDepth_m above its base (below 6 km: cumulus);
//   - other groups by h: low below 2000 m, middle below 6000 m, high above (the WMO cloud
//     etages of the mid-latitudes); a band's cover is the largest amount among its groups
//     (the amount of a group includes the layers below it: the summation principle of
//     WMO-No. 306, FM 15), its base the lowest group's, its top kDeckDepth_m above the
//     highest group's base;
//   - VVhhh (sky obscured: fog) -> low, cover 1, from the ground to hhh;
//   - a band no group reaches has cover 0 (the report says it is clear); a report without
//     sky groups or with heights "///" only says nothing, and neither does "NIL".
// Between aerodromes the bands are blended with the modified Shepard weights of Franke &
// Nielson (1980), w = ((R - d)+ / (R d))^2 with R = kStationReach_m: cover over the
// aerodromes that report the band, altitudes weighted by cover too. Farther than R from
// every aerodrome there is no cloud.
//
// The visibility (visibility_at, weather::Weather::visibility_m) is each report's drawn one
// (drawn_visibility, metar.h), "or more" (9999, CAVOK, P6SM, 10SM) counting as the model's
// clear air, kClearAirVisibility_m. It is blended as extinction (1 / V, the amount of haze)
// with the same weights, in time and between the aerodromes that report one; where the
// blend's extinction is within 1 % of the clear air's, or no aerodrome within R reports a
// visibility, it is unset.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "weather/aerodrome_table.h"
#include "weather/forecast_weather.h"
#include "weather/metar.h"

namespace cloudsvc::weather {

inline constexpr double kStationReach_m = 250000.0;
inline constexpr double kToweringCumulusDepth_m = 3000.0;
// The visibility of the model's own clear air, which an unset weather::Weather::visibility_m
// draws: -ln 0.05 over the model's sea-level extinction at 550 nm, molecules and aerosol
// (model::atmosphere; ReferenceAtmosphere.VisibilitySetsTheHaze checks the two agree).
inline constexpr double kClearAirVisibility_m = 166.4e3;
// Depth of a deck above its highest reported base, by band (low, middle, high): typical
// stratocumulus 200-900 m, altocumulus / altostratus about 1 km, cirrus 1-2 km (Sassen &
// Campbell 2001: mean cirrus depth 1.8 km).
inline constexpr double kDeckDepth_m[3] = {600.0, 1000.0, 1500.0};

// The bands a report gives over its aerodrome (NaN covers when it says nothing).
CloudColumn column_of_report(const MetarReport& report, const Aerodrome& aerodrome);

class StationWeather : public ForecastWeather {
 public:
  // From reports read from `path` (for messages). Throws WeatherFileError "<path>: line N:
  // station 'XXXX' is not in the aerodrome table" for an unknown station.
  static StationWeather from_reports(const std::vector<MetarReport>& reports, const std::string& path);
  // Merges another file's stations and reports into this one.
  void merge(const StationWeather& other);

  CloudColumn column_at(double lat_deg, double lon_deg, double utc_s) const override;
  std::optional<double> visibility_at(double lat_deg, double lon_deg, double utc_s) const override;
  std::vector<double> valid_times() const override;
  const std::string& name() const override { return name_; }

 private:
  struct Observation {
    double utc_s = 0.0;
    CloudColumn column;
    // m: the drawn one, kClearAirVisibility_m for "or more"; NaN: not reported
    double visibility_m = std::numeric_limits<double>::quiet_NaN();
    bool speci = false;  // a SPECI: replaces a METAR of the same time, wherever either stands
  };
  // Whether `later` (read after `earlier`, same time) replaces it: a SPECI is never replaced
  // by a METAR; otherwise the later report wins.
  static bool replaces(const Observation& later, const Observation& earlier) { return later.speci || !earlier.speci; }
  struct Station {
    Aerodrome aerodrome;
    std::vector<Observation> observations;  // ascending time
    std::array<double, 3> unit{};          // direction from the Earth's centre
  };
  // The observations around a time and the weight of the later (a == b, w = 0, before the
  // first and after the last).
  struct Bracket {
    const Observation& a;
    const Observation& b;
    double w;
  };
  static Bracket bracket(const Station& s, double utc_s);
  // Shepard's weight of an aerodrome at the point p (unit vector): 0 beyond kStationReach_m.
  static double station_weight(const std::array<double, 3>& p, const Station& s);
  CloudColumn station_column(const Station& s, double utc_s) const;
  double station_visibility(const Station& s, double utc_s) const;  // NaN: none

  std::vector<Station> stations_;
  std::string name_;
};

}  // namespace cloudsvc::weather
