// Global weather map: an equirectangular lat/lon grid of RGBA float channels.
//   R: coverage modulation m in [0, 1]; 0.5 = the layer's own coverage
//   G: cloud type t in [0, 1] (the map's type channel; the protocol and sim_client call it
//      "vertical development"): selects the height profile of convective layers, from
//      cells topping out at half the layer (t = 0, cumulus humilis) to the full layer
//      (t >= 0.5 = the layer as specified, congestus / cumulonimbus); stratiform layers
//      ignore it. Mapping: type_depth_fraction() in weather/cloud_layer.h
//   B: density modulation in [0, 1]; 0.5 = the layer's own density (factor 2^(2(B-0.5)))
//   A: reserved (precipitation), 0
// Texel (i, j) is centred at lon = -180 + (i + 0.5) * 360 / width,
// lat = -90 + (j + 0.5) * 180 / height (row 0 is the southernmost).
#pragma once

#include <cstdint>
#include <vector>

namespace cloudsvc::weather {

struct WeatherMap {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  // width * height * 4, row-major from the south
  // Coverage per layer slot (forecast weather, weather/forecast_frame.h): width * height * 4
  // floats on the same texels, channel k the local coverage [0, 1] of the layers whose
  // CloudLayer::coverage_channel is k (taken as it is, not modulated by R); empty: none.
  std::vector<float> layer_coverage;

  // Bilinear sample at a geodetic position, wrapping in longitude (no antimeridian
  // seam) and clamping in latitude. Returns 4 channels.
  // Poles: poleward of the outermost texel-centre row (within half a row of the pole)
  // the value is blended linearly from the row's bilinear value to the row's mean, which
  // is the value at the pole itself: every longitude then gives the same value at the
  // pole, and points on opposite sides of it a few km apart differ only slightly (plain
  // clamping would give them the values of texels a whole ring apart). Latitudes beyond
  // +-90 are clamped. Non-finite positions or an empty map give the neutral
  // {0.5, 0.5, 0.5, 0}.
  void sample(double lat_deg, double lon_deg, float out[4]) const;

  // Mean of the southernmost (north = false) or northernmost row: the value at the pole
  // that sample() blends to (the GPU sampler does the same).
  void pole_value(bool north, float out[4]) const;

  // The same for layer_coverage (4 channels; all 0 when the map has none).
  void sample_layer_coverage(double lat_deg, double lon_deg, float out[4]) const;
  void layer_coverage_pole_value(bool north, float out[4]) const;
  bool has_layer_coverage() const { return layer_coverage.size() == rgba.size() && !rgba.empty(); }

  // An upper bound of what texel n gives layer_local_coverage for any layer: its coverage
  // modulation R, and with layer coverage the largest of R and the four channels (local
  // coverage grows with R, so the bound holds for layers of either kind). For culling.
  float coverage_bound(std::size_t n) const;
};

// Deterministic procedural map from a seed: smooth noise evaluated on the unit sphere
// (3D positions, not lat/lon), so it is seamless across the antimeridian and at the poles.
// feature_km: typical size of weather systems.
WeatherMap generate_procedural_map(std::uint32_t seed, int width = 1024, int height = 512,
                                   double feature_km = 300.0);

// Combines a layer coverage c with the map's coverage modulation m (both [0, 1]):
// local = clamp(c + 1.2 * min(c, 1 - c) * (m - 0.5) * 2, 0, 1): overcast (c = 1) and clear
// (c = 0) layers stay as they are, partial layers vary with the map. Float for the GPU
// renderer's culling, double for the CPU reference and the path tracer (the shaders'
// modulated_coverage is the same formula). A non-finite coverage gives 0, a non-finite m 0.5.
float local_coverage(float layer_coverage, float m);
double local_coverage(double layer_coverage, double m);

// Local coverage of a layer whose coverage channel is `channel` (CloudLayer::coverage_channel)
// where the map gives `value`: the channel's value itself (clamped to [0, 1]) for a channel
// >= 0, else local_coverage(layer_coverage, value) with value the modulation R. With an
// upper bound of the map's value (coverage_bound), an upper bound of the local coverage.
float layer_local_coverage(int channel, float layer_coverage, float value);

}  // namespace cloudsvc::weather
