// The renderer's weather from a CIGI host's cloud layers (cigi_ig_state.h): global Weather
// Control layers 1..3 and the same layers inside Environmental Regions become the renderer's
// layers and the weather map's layer coverage, the way forecasts are drawn
// (weather/forecast_frame.h): layer id k reads slot k - 1 of the map, which holds at each
// texel the layer's coverage there: a region's inside the region, the global one outside,
// blended across the region's transition perimeter (docs/CIGI.md, "Weather"). The map has
// the renderer's resolution (1024 x 512 texels, 0.35°): a texel near a region holds the mean
// cover over it, so a region smaller than a few texels keeps its share of the cover but not
// its shape.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocol/cigi/cigi_ig_state.h"
#include "weather/cloud_layer.h"
#include "weather/weather_map.h"

namespace cloudsvc::cigi {

// The weight of a region at a point (degrees): 1 inside its rounded rectangle, falling
// linearly to 0 across its transition perimeter outside, 0 beyond (and for inactive regions).
// The rectangle lies on the tangent plane at its centre (gnomonic), its x axis rotation_deg
// clockwise from north, size_x_m along it and size_y_m across.
double region_weight(const EnvironmentalRegionControl& r, double lat_deg, double lon_deg);

struct CigiWeather {
  weather::Weather weather;      // its layers read coverage channels 0..2 (CIGI layers 1..3);
                                 // its visibility_m: cigi_visibility's
  weather::WeatherMap map;       // R, G, B neutral, A 0, and every texel's layer coverage
  std::vector<std::string> notes;  // layers dropped or trimmed where they overlapped, one line each
  std::uint64_t region_samples = 0;  // region weights evaluated for the map (at most 2^26)
};

// The visibility drawn for the host's Atmosphere Control (weather::Weather::visibility_m):
// its visibility range, m, clamped into [weather::kMinVisibility_m, weather::kMaxVisibility_m],
// whatever its atmospheric-model-enable flag (a sensor model's switch: docs/CIGI.md,
// "Weather"); unset before any Atmosphere Control (the atmosphere model's own haze).
struct CigiVisibility {
  std::optional<double> visibility_m;
  // When the clamp moved it, one line for the host, e.g. "Atmosphere Control: visibility
  // 300 m drawn as 1000 m (fog is not drawn)".
  std::optional<std::string> note;
};
CigiVisibility cigi_visibility(const IgState& state);

// The weather of the state's cloud layers on a global map of width x height texels. A
// layer's type, base, thickness and wind come from its global Weather Control, else from the
// nearest region (to `near_lat_deg`, `near_lon_deg`) that has the layer. Layers are sorted by
// base; where two overlap, the thicker keeps its altitudes and the other is cut to the part
// outside it, or dropped when less than 10 m is left (a note says which). Its visibility is
// cigi_visibility's (whose note is not among the notes).
CigiWeather cigi_weather(const IgState& state, double near_lat_deg, double near_lon_deg, int width, int height);

// The Weather Control that gives layer id k + 1 its type, altitudes and wind near a point:
// the global one, else the nearest region's that has the layer, else none. The weather drawn
// near the ownship must be made again when this changes (it flew nearer another region).
CloudLayerSet defining_layers(const IgState& state, double near_lat_deg, double near_lon_deg);

}  // namespace cloudsvc::cigi
