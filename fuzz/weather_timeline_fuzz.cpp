// Fuzz target: the weather-map timeline (weather/weather_timeline.h) as the service drives
// it: WeatherMapTile messages the protocol accepts are converted (to_map_tile,
// protocol/weather_conversion.h) and applied at a "now" (WeatherTimeline::apply, which
// resamples them into keyframes with apply_tile), and frames ask for the map at their time
// (WeatherTimeline::at), in any order: times go back when a simulator resets its clock.
// The input is a sequence of operations built with FuzzedDataProvider (fuzz/fuzzed_values.h):
// apply a tile, ask for a time, or reset to the base map. Times are in the protocol's UTC
// range, mostly within two hours of one instant so that keyframes interact; tiles are at
// most 9 x 9 texels, mostly within valid bounds.
// Invariants checked besides the sanitizers':
//  - a tile that protocol::validate() accepts has no MapTile::problem() (the renderer
//    throws on those, CloudRenderer::apply_tile): validate() applies the same rules
//    (weather/map_tile.h), so this checks that to_map_tile() keeps what they judged;
//  - at() always returns two keyframes of the base map's size whose values are finite and
//    in [0, 1], with a weight in [0, 1];
//  - at most kMaxKeyframes keyframes are kept.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_values.h"
#include "protocol/validate.h"
#include "protocol/weather_conversion.h"
#include "weather/weather_map.h"
#include "weather/weather_timeline.h"

namespace {

using namespace cloudsvc;

// A small procedural base map, as CloudRenderer::set_weather builds a large one: apply_tile
// visits every texel of every keyframe, so a small map keeps runs fast.
const weather::WeatherMap& base_map() {
  static const weather::WeatherMap map = weather::generate_procedural_map(7, 48, 24);
  return map;
}

// A value in [lo, hi] most of the time, else any double (boundaries, NaN, huge).
double mostly_in(FuzzedDataProvider& in, double lo, double hi) {
  return in.ConsumeIntegralInRange<int>(0, 3) != 0 ? in.ConsumeFloatingPointInRange<double>(lo, hi)
                                                   : fuzz::any_double(in);
}

// A tile that is valid most of the time (bounds within the protocol's ranges, values in
// [0, 1] but sometimes one), so that runs build up several keyframes.
protocol::WeatherMapTile make_tile(FuzzedDataProvider& in) {
  protocol::WeatherMapTile t;
  t.lat_min_deg = mostly_in(in, -90.0, 90.0);
  t.lat_max_deg = t.lat_min_deg + mostly_in(in, 0.0, 180.0);
  t.lon_min_deg = mostly_in(in, -180.0, 180.0);
  t.lon_max_deg = t.lon_min_deg + mostly_in(in, 0.0, 360.0);
  t.width = in.ConsumeIntegralInRange<std::uint32_t>(1, 9);
  t.height = in.ConsumeIntegralInRange<std::uint32_t>(1, 9);
  t.channels = in.ConsumeIntegralInRange<std::uint8_t>(1, 15);
  t.valid_at_utc_s = fuzz::utc_time(in);
  t.data.resize(static_cast<std::size_t>(t.width) * t.height * t.channel_count());
  for (float& v : t.data) v = in.ConsumeProbability<float>();
  if (in.ConsumeIntegralInRange<int>(0, 7) == 0) {  // sometimes one value of any kind
    t.data[in.ConsumeIntegralInRange<std::size_t>(0, t.data.size() - 1)] = fuzz::any_float(in);
  }
  return t;
}

void check_map(const weather::WeatherMap* m) {
  const weather::WeatherMap& base = base_map();
  FUZZ_CHECK(m != nullptr, "at() returned no keyframe");
  FUZZ_CHECK(m->width == base.width && m->height == base.height && m->rgba.size() == base.rgba.size(),
             "a keyframe changed size");
  for (const float v : m->rgba) FUZZ_CHECK(v >= 0.0f && v <= 1.0f, "a map value outside [0, 1] or NaN");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  // On the heap, so that AddressSanitizer sees a read past the object.
  auto timeline = std::make_unique<weather::WeatherTimeline>(base_map());
  for (int op = 0; op < 64 && in.remaining_bytes() > 0; ++op) {
    switch (in.ConsumeIntegralInRange<int>(0, 7)) {
      case 0:
        timeline->reset(base_map());
        break;
      case 1:
      case 2:
      case 3: {
        const protocol::WeatherMapTile tile = make_tile(in);
        const double now = fuzz::utc_time(in);
        if (protocol::validate(protocol::Message(tile))) break;  // the service refuses it
        const weather::MapTile converted = to_map_tile(tile);
        const std::string problem = converted.problem();
        if (!problem.empty()) std::fprintf(stderr, "MapTile::problem: %s\n", problem.c_str());
        FUZZ_CHECK(problem.empty(), "a tile the protocol accepts has a MapTile::problem()");
        timeline->apply(converted, now);
        break;
      }
      default: {
        const weather::WeatherTimeline::Blend b = timeline->at(fuzz::utc_time(in));
        check_map(b.from);
        check_map(b.to);
        FUZZ_CHECK(b.weight >= 0.0f && b.weight <= 1.0f, "blend weight outside [0, 1] or NaN");
        break;
      }
    }
    FUZZ_CHECK(timeline->keyframe_count() <= weather::WeatherTimeline::kMaxKeyframes,
               "more keyframes kept than kMaxKeyframes");
  }
  return 0;
}
