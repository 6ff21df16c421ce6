// Forecast weather made in tests: the bands at each point given by a function, at one step.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "weather/forecast_weather.h"

namespace cloudsvc::test {

class FunctionForecast : public weather::ForecastWeather {
 public:
  using Columns = std::function<weather::CloudColumn(double lat_deg, double lon_deg)>;
  FunctionForecast(std::string name, Columns columns, double valid_utc_s = 0.0)
      : name_(std::move(name)), columns_(std::move(columns)), valid_utc_s_(valid_utc_s) {}

  weather::CloudColumn column_at(double lat_deg, double lon_deg, double) const override {
    return columns_(lat_deg, lon_deg);
  }
  std::vector<double> valid_times() const override { return {valid_utc_s_}; }
  const std::string& name() const override { return name_; }

 private:
  std::string name_;
  Columns columns_;
  double valid_utc_s_;
};

}  // namespace cloudsvc::test
