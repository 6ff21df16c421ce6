// Named weather presets (table in docs/WEATHER.md). Density scale and droplet size come
// from the cloud type's traits (weather/cloud_layer.cpp); altitudes are m above the
// ellipsoid; wind is [east, north] m/s, increasing with height as in a typical
// mid-latitude profile (~5-10 m/s in the boundary layer, 25-40 m/s near the jet stream).
#include "weather/presets.h"


namespace cloudsvc::weather {
namespace {

struct LayerSpec {
  CloudType type;
  double base_m, top_m, coverage, east_mps, north_mps;
};

struct PresetSpec {
  std::string_view name;
  std::uint32_t map_seed;
  std::vector<LayerSpec> layers;  // listed by base altitude
};

const std::vector<PresetSpec>& presets() {
  static const std::vector<PresetSpec> table = {
      {"clear", 1, {}},
      // Fair-weather cumulus: isolated cells, ~1/3 of the sky (3-4 oktas, "SCT").
      {"scattered-cumulus", 2, {{CloudType::Cumulus, 1200, 2600, 0.35, 6, 2}}},
      // Deeper cumulus covering ~2/3 of the sky (5-7 oktas, "BKN") under a thin cirrus
      // veil near the tropopause, in the faster upper-level wind.
      {"broken-cumulus",
       3,
       {{CloudType::Cumulus, 1000, 2800, 0.65, 8, 3},
        {CloudType::Cirrus, 9000, 10000, 0.2, 30, 8}}},
      // Low, thin, complete stratus deck (8 oktas, "OVC"), light wind.
      {"overcast-stratus", 4, {{CloudType::Stratus, 400, 900, 1.0, 4, -2}}},
      // Marine-style stratocumulus sheet with small breaks (~7 oktas).
      {"stratocumulus-deck", 5, {{CloudType::Stratocumulus, 1200, 1800, 0.85, 7, 1}}},
      // Thunderstorms reaching the tropopause among low fair-weather cumulus; their anvils
      // (weather::Anvil) merge into a shield where the weather map clusters them.
      // The cumulus layer sits below the Cb base: layers may not overlap in altitude.
      {"cumulonimbus",
       6,
       {{CloudType::Cumulus, 500, 850, 0.25, 5, 2},
        {CloudType::Cumulonimbus, 900, 11000, 0.35, 10, 4}}},
  };
  return table;
}

}  // namespace

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const PresetSpec& p : presets()) names.emplace_back(p.name);
  return names;
}

std::optional<Weather> preset(std::string_view name) {
  for (const PresetSpec& p : presets()) {
    if (p.name != name) continue;
    Weather w;
    w.name = std::string(p.name);
    w.map_seed = p.map_seed;
    for (const LayerSpec& s : p.layers) {
      CloudLayer l = default_layer(s.type);
      l.base_m = s.base_m;
      l.top_m = s.top_m;
      l.coverage = s.coverage;
      l.wind = {s.east_mps, s.north_mps};
      w.layers.push_back(l);
    }
    return w;
  }
  return std::nullopt;
}

}  // namespace cloudsvc::weather
