// Named weather presets (weather/presets.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "weather/presets.h"
#include "weather/weather_json.h"

namespace cloudsvc::weather {
namespace {

const char* const kRequired[] = {"clear",          "scattered-cumulus",  "broken-cumulus",
                                 "overcast-stratus", "stratocumulus-deck", "cumulonimbus"};

TEST(Presets, AllListedNamesExistAndValidate) {
  const std::vector<std::string> names = preset_names();
  for (const char* name : kRequired) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  for (const std::string& name : names) {
    const auto w = preset(name);
    ASSERT_TRUE(w.has_value()) << name;
    EXPECT_EQ(w->name, name);
    EXPECT_EQ(validate(*w), "") << name;
  }
}

TEST(Presets, UnknownNameIsNullopt) {
  EXPECT_FALSE(preset("hurricane").has_value());
  EXPECT_FALSE(preset("").has_value());
  EXPECT_FALSE(preset("Clear").has_value());
}

TEST(Presets, Contents) {
  EXPECT_TRUE(preset("clear")->layers.empty());

  const Weather sct = *preset("scattered-cumulus");
  ASSERT_EQ(sct.layers.size(), 1u);
  EXPECT_EQ(sct.layers[0].type, CloudType::Cumulus);
  EXPECT_NEAR(sct.layers[0].coverage, 0.35, 0.05);

  const Weather bkn = *preset("broken-cumulus");
  ASSERT_EQ(bkn.layers.size(), 2u);
  EXPECT_EQ(bkn.layers[0].type, CloudType::Cumulus);
  EXPECT_NEAR(bkn.layers[0].coverage, 0.65, 0.05);
  EXPECT_EQ(bkn.layers[1].type, CloudType::Cirrus);
  EXPECT_GE(bkn.layers[1].base_m, 8500.0);
  EXPECT_LT(bkn.layers[1].coverage, 0.4);

  const Weather ovc = *preset("overcast-stratus");
  ASSERT_EQ(ovc.layers.size(), 1u);
  EXPECT_EQ(ovc.layers[0].type, CloudType::Stratus);
  EXPECT_EQ(ovc.layers[0].coverage, 1.0);
  EXPECT_LT(ovc.layers[0].top_m, 1000.0);

  const Weather sc = *preset("stratocumulus-deck");
  ASSERT_EQ(sc.layers.size(), 1u);
  EXPECT_EQ(sc.layers[0].type, CloudType::Stratocumulus);

  const Weather cb = *preset("cumulonimbus");
  const auto it = std::find_if(cb.layers.begin(), cb.layers.end(),
                               [](const CloudLayer& l) { return l.type == CloudType::Cumulonimbus; });
  ASSERT_NE(it, cb.layers.end());
  EXPECT_GE(it->top_m, 10000.0);
  EXPECT_LE(it->base_m, 1500.0);
  EXPECT_TRUE(std::any_of(cb.layers.begin(), cb.layers.end(),
                          [](const CloudLayer& l) { return l.type == CloudType::Cumulus; }));
}

TEST(Presets, EachHasWindAndDistinctSeed) {
  std::vector<std::uint32_t> seeds;
  for (const std::string& name : preset_names()) {
    const Weather w = *preset(name);
    seeds.push_back(w.map_seed);
    for (const CloudLayer& l : w.layers) {
      EXPECT_GT(std::hypot(l.wind.east_mps, l.wind.north_mps), 1.0) << name;
    }
  }
  std::sort(seeds.begin(), seeds.end());
  EXPECT_EQ(std::adjacent_find(seeds.begin(), seeds.end()), seeds.end());
}

TEST(Presets, RoundTripThroughJson) {
  for (const std::string& name : preset_names()) {
    const Weather w = *preset(name);
    const Weather back = parse_weather_json(to_json(w), name + ".json");
    EXPECT_EQ(to_json(back), to_json(w)) << name;
  }
}

}  // namespace
}  // namespace cloudsvc::weather
