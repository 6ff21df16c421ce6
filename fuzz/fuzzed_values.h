// Values for the structure-aware fuzz targets (protocol_validate, weather_timeline): they
// build messages field by field from libFuzzer's bytes (FuzzedDataProvider), so numbers
// must hit the protocol's range boundaries, non-finite values and ordinary in-range values
// often enough for validate() and the code behind it to see all of them.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "protocol/limits.h"

namespace cloudsvc::fuzz {

// Boundaries of the ranges in protocol/limits.h and weather/cloud_layer.h, values just
// outside them, and the IEEE special cases.
inline double special_double(FuzzedDataProvider& in) {
  using L = std::numeric_limits<double>;
  namespace p = protocol;
  static const std::array<double, 34> kValues = {
      L::quiet_NaN(), -L::quiet_NaN(), L::infinity(), -L::infinity(), 0.0, -0.0,
      L::max(), -L::max(), L::min(), L::denorm_min(), -L::denorm_min(), 1.0, 0.5,
      90.0, -90.0, 180.0, -180.0, 360.0, -360.0, p::kMaxHfov_deg, p::kMinAltitude_m,
      p::kMaxAltitude_m, p::kMaxSpeed_mps, p::kMinUtc_s, p::kMaxUtc_s,
      std::nextafter(p::kMaxUtc_s, 0.0), p::kMinLayerBase_m, p::kMaxLayerTop_m,
      p::kMinLayerThickness_m, p::kMaxDensityScale, p::kMinDropletDiameter_um,
      p::kMaxDropletDiameter_um, p::kMaxWindSpeed_mps, std::nextafter(1.0, 2.0)};
  return kValues[in.ConsumeIntegralInRange<std::size_t>(0, kValues.size() - 1)];
}

// A double: an angle-sized value, a fraction, a special value, an altitude- or time-sized
// value, or any double at all.
inline double any_double(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 4)) {
    case 0:
      return in.ConsumeFloatingPointInRange<double>(-400.0, 400.0);
    case 1:
      return in.ConsumeProbability<double>();
    case 2:
      return special_double(in);
    case 3:
      return in.ConsumeFloatingPointInRange<double>(-1e5, 1e10);
    default:
      return in.ConsumeFloatingPoint<double>();
  }
}

// A float for tile data: mostly in [0, 1], sometimes any double's value (rounded to float).
inline float any_float(FuzzedDataProvider& in) {
  return in.ConsumeBool() ? in.ConsumeProbability<float>() : static_cast<float>(any_double(in));
}

// A UTC time inside the protocol's range [kMinUtc_s, kMaxUtc_s): mostly within two hours of
// a fixed instant, so that keyframes and "now" interact, sometimes anywhere in the range.
inline double utc_time(FuzzedDataProvider& in) {
  constexpr double kAround = 1782043200.0;  // 2026-06-21T12:00:00Z
  if (in.ConsumeBool()) return kAround + in.ConsumeIntegralInRange<int>(-7200, 7200);
  return in.ConsumeFloatingPointInRange<double>(protocol::kMinUtc_s,
                                                std::nextafter(protocol::kMaxUtc_s, 0.0));
}

// A string of up to max_bytes arbitrary bytes.
inline std::string any_string(FuzzedDataProvider& in, std::size_t max_bytes) {
  return in.ConsumeRandomLengthString(max_bytes);
}

}  // namespace cloudsvc::fuzz
