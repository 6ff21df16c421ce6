// Weather from numerical forecasts: the cloud fields of one or more GRIB2 files
// (grib_reader.h), grouped into steps by validity time, sampled at any point and time.
// Each step is a keyframe; between two steps every field is blended linearly in time (as
// the weather timeline blends its keyframes), before and after them the nearest step holds.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "weather/forecast_weather.h"
#include "weather/grib_reader.h"

namespace cloudsvc::weather {

class GriddedWeather : public ForecastWeather {
 public:
  // Reads GRIB2 files (WeatherFileError naming the file on any problem).
  static GriddedWeather load_grib(const std::vector<std::string>& paths);
  // From messages already read (e.g. by tests).
  static GriddedWeather from_messages(std::vector<GribCloudMessage> messages, std::string name);

  // The bands over a point at a time (UTC seconds), blended between the steps around it.
  CloudColumn column_at(double lat_deg, double lon_deg, double utc_s) const override;
  // Validity times of the steps, ascending (UTC seconds).
  std::vector<double> valid_times() const override;
  const std::string& name() const override { return name_; }

 private:
  struct Step {
    double valid_utc_s = 0.0;
    std::vector<GribCloudMessage> fields;
  };
  CloudColumn column_in_step(const Step& step, double lat_deg, double lon_deg) const;

  std::vector<Step> steps_;  // ascending validity time
  std::optional<GribCloudMessage> orography_;  // the ground's height, when a file gives it
  std::string name_;
};

}  // namespace cloudsvc::weather
