#include "service/demo_scenes.h"

namespace cloudsvc {

// Zurich area (47.45 N, 8.56 E), midsummer 2026: local solar noon is about 11:26 UTC,
// sunset about 19:26 UTC, end of civil twilight about 20:10 UTC.
const std::vector<DemoScene>& demo_scenes() {
  static const std::vector<DemoScene> scenes = {
      {"below-broken-cumulus-noon", "500 m below a broken cumulus layer at noon, looking up 25 deg",
       {47.45, 8.56, 500.0}, {200.0, 25.0, 0.0}, "2026-06-21T11:30:00Z", 75.0, "broken-cumulus"},
      {"inside-stratus", "inside an overcast stratus deck (400-900 m) at 650 m",
       {47.45, 8.56, 650.0}, {90.0, 0.0, 0.0}, "2026-06-21T11:30:00Z", 75.0, "overcast-stratus"},
      {"above-stratocumulus-sunset", "above a stratocumulus deck at sunset, ground and shadows through the gaps",
       {47.45, 8.56, 3000.0}, {300.0, -12.0, 0.0}, "2026-06-21T19:05:00Z", 75.0, "stratocumulus-deck"},
      {"from-30km", "from 30 km altitude over broken cumulus, looking down 25 deg",
       {47.45, 8.56, 30000.0}, {180.0, -25.0, 0.0}, "2026-06-21T11:30:00Z", 75.0, "broken-cumulus"},
      {"night", "scattered cumulus at night, after civil twilight (sun 10 deg below the horizon), looking west",
       {47.45, 8.56, 500.0}, {315.0, 10.0, 0.0}, "2026-06-21T20:45:00Z", 75.0, "scattered-cumulus"},
      {"cumulonimbus", "a cumulonimbus field in the afternoon from 13 km, anvils merged into a shield",
       {47.45, 8.56, 13000.0}, {135.0, -15.0, 0.0}, "2026-06-21T14:00:00Z", 75.0, "cumulonimbus"},
  };
  return scenes;
}

}  // namespace cloudsvc
