// CIGI cloud layers -> the renderer's weather (protocol/cigi/cigi_weather.h): where a region's
// weather holds, how its perimeter blends, which altitudes the layers get, and that the
// result is weather the renderer accepts.
#include <gtest/gtest.h>

#include <cmath>

#include "cigi_test_support.h"
#include "protocol/cigi/cigi_weather.h"
#include "weather/cloud_water.h"
#include "weather/sphere_geometry.h"

namespace cloudsvc::cigi {
namespace {

// The point `north_m` north and `east_m` east of (lat, lon) on the sphere (small offsets).
std::pair<double, double> offset(double lat, double lon, double north_m, double east_m) {
  const double r = weather::kMeanEarthRadius_m;
  return {lat + north_m / r / weather::kRadPerDeg, lon + east_m / (r * std::cos(lat * weather::kRadPerDeg)) / weather::kRadPerDeg};
}

EnvironmentalRegionControl region(double lat, double lon, float size_x, float size_y, float perimeter, float rotation = 0.0f) {
  EnvironmentalRegionControl r;
  r.region_id = 3;
  r.lat_deg = lat;
  r.lon_deg = lon;
  r.size_x_m = size_x;
  r.size_y_m = size_y;
  r.corner_radius_m = 0.0f;
  r.rotation_deg = rotation;
  r.transition_perimeter_m = perimeter;
  return r;
}

double weight_at(const EnvironmentalRegionControl& r, double north_m, double east_m) {
  const auto [lat, lon] = offset(r.lat_deg, r.lon_deg, north_m, east_m);
  return region_weight(r, lat, lon);
}

TEST(CigiWeather, ARegionHoldsInsideAndFadesAcrossItsPerimeter) {
  const EnvironmentalRegionControl r = region(46.0, 7.0, 40000.0f, 10000.0f, 8000.0f);
  EXPECT_EQ(weight_at(r, 0.0, 0.0), 1.0);
  EXPECT_EQ(weight_at(r, 19000.0, 4000.0), 1.0);  // x (north) half 20 km, y (east) half 5 km
  EXPECT_NEAR(weight_at(r, 24000.0, 0.0), 0.5, 0.01) << "4 km into the 8 km perimeter";
  EXPECT_NEAR(weight_at(r, 0.0, 7000.0), 0.75, 0.01);
  EXPECT_EQ(weight_at(r, 0.0, 14000.0), 0.0);
  // Rotated 90°: x points east.
  const EnvironmentalRegionControl turned = region(46.0, 7.0, 40000.0f, 10000.0f, 0.0f, 90.0f);
  EXPECT_EQ(weight_at(turned, 0.0, 15000.0), 1.0);
  EXPECT_EQ(weight_at(turned, 15000.0, 0.0), 0.0);
  // Rounded corners: the corner point is outside, the edge midpoint inside.
  EnvironmentalRegionControl rounded = region(46.0, 7.0, 20000.0f, 20000.0f, 0.0f);
  rounded.corner_radius_m = 5000.0f;
  EXPECT_EQ(weight_at(rounded, 9800.0, 9800.0), 0.0);
  EXPECT_EQ(weight_at(rounded, 9800.0, 0.0), 1.0);
  // Inactive regions and the far side of the Earth weigh nothing.
  EnvironmentalRegionControl off = r;
  off.state = 0;
  EXPECT_EQ(region_weight(off, 46.0, 7.0), 0.0);
  EXPECT_EQ(region_weight(r, -46.0, -173.0), 0.0);
}

WeatherControl layer(std::uint8_t id, std::uint8_t type, float base, float thickness, float coverage_pct) {
  WeatherControl w;
  w.layer_id = id;
  w.cloud_type = type;
  w.base_elevation_m = base;
  w.thickness_m = thickness;
  w.coverage_pct = coverage_pct;
  return w;
}


float slot_at(const weather::WeatherMap& m, int slot, double lat, double lon) {
  float c[4];
  m.sample_layer_coverage(lat, lon, c);
  return c[slot];
}

TEST(CigiWeather, AGlobalDeckWithARegionalHole) {
  IgState s;
  WeatherControl deck = layer(1, 10, 800.0f, 600.0f, 100.0f);
  deck.wind_horizontal_mps = 10.0f;
  deck.wind_direction_deg = 270.0f;  // from the west
  EnvironmentalRegionControl hole = region(46.0, 7.0, 200000.0f, 200000.0f, 100000.0f);
  WeatherControl clear = layer(1, 10, 800.0f, 600.0f, 0.0f);
  clear.scope = WeatherScope::Regional;
  clear.entity_or_region_id = hole.region_id;
  EXPECT_TRUE(s.apply(host_datagram({deck, hole, clear})).empty());
  const CigiWeather w = cigi_weather(s, 46.0, 7.0, 1024, 512);
  EXPECT_EQ(weather::validate(w.weather), "");
  ASSERT_EQ(w.weather.layers.size(), 1u);
  const weather::CloudLayer& l = w.weather.layers[0];
  EXPECT_EQ(l.type, weather::CloudType::Stratus);
  EXPECT_EQ(l.base_m, 800.0);
  EXPECT_EQ(l.top_m, 1400.0);
  EXPECT_EQ(l.coverage_channel, 0);
  EXPECT_NEAR(l.wind.east_mps, 10.0, 1e-5);
  EXPECT_NEAR(l.wind.north_mps, 0.0, 1e-5);
  EXPECT_NEAR(slot_at(w.map, 0, 46.0, 7.0), 0.0, 0.01) << "the hole";
  EXPECT_NEAR(slot_at(w.map, 0, 30.0, -40.0), 1.0, 1e-6) << "the deck elsewhere";
  const auto [lat, lon] = offset(46.0, 7.0, 150000.0, 0.0);  // half way through the perimeter
  EXPECT_NEAR(slot_at(w.map, 0, lat, lon), 0.5, 0.08);
  EXPECT_EQ(slot_at(w.map, 1, 30.0, -40.0), 0.0f) << "no layer 2";
  EXPECT_TRUE(w.notes.empty());
}

TEST(CigiWeather, ALayerOnlyInARegionAndOverlappingLayers) {
  IgState s;
  EnvironmentalRegionControl storm = region(10.0, 100.0, 60000.0f, 60000.0f, 0.0f);
  WeatherControl cb = layer(2, 6, 1200.0f, 9000.0f, 80.0f);  // 1200 .. 10200 m, the thickest
  cb.scope = WeatherScope::Regional;
  cb.entity_or_region_id = storm.region_id;
  WeatherControl sc = layer(1, 9, 600.0f, 1400.0f, 50.0f);    // 600 .. 2000 m: cut to 600 .. 1200
  WeatherControl ac = layer(3, 1, 4000.0f, 500.0f, 30.0f);    // inside the cumulonimbus: dropped
  EXPECT_TRUE(s.apply(host_datagram({storm, cb, sc, ac})).empty());
  const CigiWeather w = cigi_weather(s, 10.0, 100.0, 512, 256);
  EXPECT_EQ(weather::validate(w.weather), "");
  ASSERT_EQ(w.weather.layers.size(), 2u);
  EXPECT_EQ(w.weather.layers[0].type, weather::CloudType::Stratocumulus);
  EXPECT_EQ(w.weather.layers[0].top_m, 1200.0);
  EXPECT_EQ(w.weather.layers[1].type, weather::CloudType::Cumulonimbus);
  EXPECT_EQ(w.weather.layers[1].coverage_channel, 1);
  ASSERT_EQ(w.notes.size(), 2u);
  EXPECT_EQ(w.notes[0], "layer 1 overlaps layer 2: drawn from 600 to 1200 m");
  EXPECT_EQ(w.notes[1], "layer 3 lies within layer 2: not drawn");
  // A 60 km region on 0.7° texels (78 km): it keeps its share of the texels' cover.
  double sum = 0.0;
  for (int j = 0; j < w.map.height; ++j)
    for (int i = 0; i < w.map.width; ++i) {
      const double lat = -90.0 + (j + 0.5) * 180.0 / w.map.height;
      const double texel_m2 = std::pow(weather::kMeanEarthRadius_m * weather::kRadPerDeg, 2) * (180.0 / w.map.height) *
                              (360.0 / w.map.width) * std::cos(lat * weather::kRadPerDeg);
      sum += w.map.layer_coverage[(static_cast<std::size_t>(j) * w.map.width + i) * 4 + 1] * texel_m2;
    }
  EXPECT_NEAR(sum / (0.8 * 60000.0 * 60000.0), 1.0, 0.02) << "the storm's cloud area, m2";
  EXPECT_EQ(slot_at(w.map, 1, 10.0, 110.0), 0.0f) << "and nowhere else";
  EXPECT_NEAR(slot_at(w.map, 0, 10.0, 110.0), 0.5, 1e-6);
}

// Two regions define layer 1 differently (stratocumulus in the west, cumulus in the east): the
// layer's type and altitudes are the nearer region's, so the weather drawn must change as
// the ownship flies from one to the other; a global layer 1 wins everywhere.
TEST(CigiWeather, TheDefiningLayerIsTheNearerRegionsUnlessAGlobalOneIsGiven) {
  IgState s;
  EnvironmentalRegionControl west = region(46.0, 6.0, 30000.0f, 30000.0f, 0.0f);
  west.region_id = 1;
  EnvironmentalRegionControl east = region(46.0, 8.0, 30000.0f, 30000.0f, 0.0f);
  east.region_id = 2;
  WeatherControl stratocumulus = layer(1, 9, 400.0f, 500.0f, 100.0f);
  stratocumulus.scope = WeatherScope::Regional;
  stratocumulus.entity_or_region_id = west.region_id;
  WeatherControl cumulus = layer(1, 7, 1200.0f, 1500.0f, 40.0f);
  cumulus.scope = WeatherScope::Regional;
  cumulus.entity_or_region_id = east.region_id;
  EXPECT_TRUE(s.apply(host_datagram({west, east, stratocumulus, cumulus})).empty());
  const CloudLayerSet near_west = defining_layers(s, 46.0, 6.2), near_east = defining_layers(s, 46.0, 7.9);
  ASSERT_TRUE(near_west[0] && near_east[0]);
  EXPECT_EQ(near_west[0]->cloud_type, 9);
  EXPECT_EQ(near_east[0]->cloud_type, 7);
  EXPECT_FALSE(near_west[1] || near_west[2]);
  EXPECT_EQ(cigi_weather(s, 46.0, 6.2, 64, 32).weather.layers.at(0).base_m, 400.0);
  EXPECT_EQ(cigi_weather(s, 46.0, 7.9, 64, 32).weather.layers.at(0).base_m, 1200.0);
  const WeatherControl global = layer(1, 5, 3000.0f, 800.0f, 60.0f);
  EXPECT_TRUE(s.apply(host_datagram({global})).empty());
  EXPECT_EQ(defining_layers(s, 46.0, 6.2), defining_layers(s, 46.0, 7.9));
  EXPECT_EQ(defining_layers(s, 46.0, 7.9)[0]->cloud_type, 5);
}

// Atmosphere Control's visibility range (m) is the weather's visibility_m, whatever the
// atmospheric-model-enable flag (a sensor model's switch), with or without cloud layers.
TEST(CigiWeather, TheAtmosphereControlsVisibilityIsTheWeathers) {
  IgState s;
  EXPECT_FALSE(cigi_visibility(s).visibility_m) << "before any Atmosphere Control: the renderer's own haze";
  EXPECT_FALSE(cigi_weather(s, 46.0, 7.0, 64, 32).weather.visibility_m);
  AtmosphereControl a;
  a.model_enable = false;
  a.visibility_m = 8000.0f;
  EXPECT_TRUE(s.apply(host_datagram({a})).empty());
  EXPECT_EQ(cigi_visibility(s).visibility_m, 8000.0);
  EXPECT_FALSE(cigi_visibility(s).note);
  EXPECT_EQ(cigi_weather(s, 46.0, 7.0, 64, 32).weather.visibility_m, 8000.0) << "no cloud layers";
  a.model_enable = true;
  a.visibility_m = 45000.0f;
  EXPECT_TRUE(s.apply(host_datagram({a, layer(1, 7, 1000.0f, 1500.0f, 40.0f)})).empty());
  const CigiWeather w = cigi_weather(s, 46.0, 7.0, 64, 32);
  EXPECT_EQ(w.weather.visibility_m, 45000.0);
  EXPECT_EQ(w.weather.layers.size(), 1u);
  EXPECT_EQ(weather::validate(w.weather), "");
  EXPECT_TRUE(w.notes.empty());
}

// A visibility outside [kMinVisibility_m, kMaxVisibility_m] is drawn at the nearer end, with a
// note for the host (an IG Message), not refused; the weather stays one the renderer accepts.
TEST(CigiWeather, AVisibilityOutsideTheDrawnRangeIsClampedWithANote) {
  struct Case {
    float sent_m;
    double drawn_m;
    const char* note;
  };
  for (const Case& c : {Case{300.0f, weather::kMinVisibility_m,
                             "Atmosphere Control: visibility 300 m drawn as 1000 m (fog is not drawn)"},
                        Case{0.0f, weather::kMinVisibility_m,
                             "Atmosphere Control: visibility 0 m drawn as 1000 m (fog is not drawn)"},
                        Case{999.5f, weather::kMinVisibility_m,
                             "Atmosphere Control: visibility 999.5 m drawn as 1000 m (fog is not drawn)"},
                        Case{5.0e6f, weather::kMaxVisibility_m,
                             "Atmosphere Control: visibility 5000000 m drawn as 1000000 m (the largest drawn)"},
                        Case{1000.0f, 1000.0, ""}, Case{1.0e6f, 1.0e6, ""}}) {
    SCOPED_TRACE(c.sent_m);
    IgState s;
    AtmosphereControl a;
    a.visibility_m = c.sent_m;
    EXPECT_TRUE(s.apply(host_datagram({a})).empty()) << "not a rejection";
    EXPECT_EQ(s.atmosphere()->visibility_m, c.sent_m) << "the state keeps what the host sent";
    const CigiVisibility v = cigi_visibility(s);
    EXPECT_EQ(v.visibility_m, c.drawn_m);
    EXPECT_EQ(v.note.value_or(""), c.note);
    const CigiWeather w = cigi_weather(s, 0.0, 0.0, 64, 32);
    EXPECT_EQ(w.weather.visibility_m, c.drawn_m);
    EXPECT_EQ(weather::validate(w.weather), "");
    EXPECT_TRUE(w.notes.empty()) << "the note is cigi_visibility's alone";
  }
}

// A Weather Control's aerosol concentration (g/m^3) is the layer's cloud water content: it
// sets the density scale in the type's droplets (weather/cloud_water.h); 0, which hosts send
// when they do not model it, keeps the type's typical water; more than the renderer draws is
// drawn at its most, with a note.
TEST(CigiWeather, AWeatherControlsAerosolIsTheLayersWaterContent) {
  IgState s;
  WeatherControl cumulus = layer(1, 7, 1200.0f, 1500.0f, 40.0f);
  WeatherControl stratus = layer(2, 10, 400.0f, 300.0f, 90.0f);
  stratus.aerosol_gpm3 = 0.0f;
  cumulus.aerosol_gpm3 = 1.0f;
  EXPECT_TRUE(s.apply(host_datagram({cumulus, stratus})).empty());
  CigiWeather w = cigi_weather(s, 46.0, 7.0, 64, 32);
  ASSERT_EQ(w.weather.layers.size(), 2u);
  const weather::CloudLayer& st = w.weather.layers[0];  // sorted by base
  const weather::CloudLayer& cu = w.weather.layers[1];
  EXPECT_EQ(st.density_scale, weather::cloud_type_traits(weather::CloudType::Stratus).default_density_scale);
  // 1 g/m^3 in 20 um droplets: 300 cm^-3 of them hold 4/3 pi (10 um)^3 * 1e6 g/m^3 * 3e8 /m^3
  // = 1.2566 g/m^3, so the scale is 0.796 (the type's typical 0.5 g/m^3 is 0.40)
  EXPECT_EQ(cu.droplet_diameter_um, 20.0);
  EXPECT_NEAR(cu.density_scale, 1.0 / 1.2566371, 1e-6);
  EXPECT_NEAR(weather::density_scale_for_water_content(0.5, 20.0),
              weather::cloud_type_traits(weather::CloudType::Cumulus).default_density_scale, 0.005);
  EXPECT_TRUE(w.notes.empty());
  EXPECT_EQ(weather::validate(w.weather), "");
  // Twice the water, twice the extinction.
  cumulus.aerosol_gpm3 = 2.0f;
  EXPECT_TRUE(s.apply(host_datagram({cumulus})).empty());
  EXPECT_NEAR(cigi_weather(s, 46.0, 7.0, 64, 32).weather.layers.at(1).density_scale, 2.0 / 1.2566371, 1e-6);
  // More water than the renderer's largest density scale holds in these droplets.
  cumulus.aerosol_gpm3 = 20.0f;
  EXPECT_TRUE(s.apply(host_datagram({cumulus})).empty()) << "not a rejection";
  w = cigi_weather(s, 46.0, 7.0, 64, 32);
  EXPECT_EQ(w.weather.layers.at(1).density_scale, weather::kMaxDensityScale);
  ASSERT_EQ(w.notes.size(), 1u);
  EXPECT_EQ(w.notes[0], "layer 1: water content 20 g/m^3 drawn as 12.566371 g/m^3 (the most drawn in its droplets)");
  EXPECT_EQ(weather::validate(w.weather), "");
  // A negative or non-finite concentration is refused with the packet (cigi_checks): the
  // layer keeps the water it had.
  for (const float bad : {-1.0f, std::nanf(""), INFINITY}) {
    cumulus.aerosol_gpm3 = bad;
    DatagramWriter writer(ByteOrder::Big);
    writer.add(IgControl{});
    writer.add(cumulus);
    const HostDatagram d = read_host_datagram(writer.bytes());
    ASSERT_EQ(d.rejections.size(), 1u) << bad;
    EXPECT_NE(d.rejections[0].reason.find("aerosol_gpm3"), std::string::npos) << d.rejections[0].reason;
    EXPECT_TRUE(s.apply(d).empty());
  }
  EXPECT_EQ(cigi_weather(s, 46.0, 7.0, 64, 32).weather.layers.at(1).density_scale, weather::kMaxDensityScale);
}

// Regions that pass every check but would cost the coverage map billions of samples (long
// and thinner than a texel, or 64 of them the size of a hemisphere) are drawn within a bounded
// number of samples, so a datagram cannot stall the IG; ordinary regions keep their full
// sampling (ARegionHoldsInside..., the storm's 2 % above), and texels wholly inside a region
// take its cover.
TEST(CigiWeather, PathologicalRegionsAreDrawnWithinABoundedNumberOfSamples) {
  for (const bool thin : {true, false}) {
    SCOPED_TRACE(thin ? "64 regions 20 000 km x 1 m" : "64 regions 20 000 km square");
    IgState s;
    for (std::uint16_t id = 1; id <= 64; ++id) {
      EnvironmentalRegionControl r = region(-60.0 + 1.9 * id, -170.0 + 5.3 * id, 2.0e7f, thin ? 1.0f : 2.0e7f, 1000.0f,
                                            45.0f + id);
      r.region_id = id;
      WeatherControl cb = layer(1, 6, 1000.0f, 8000.0f, 80.0f);
      cb.scope = WeatherScope::Regional;
      cb.entity_or_region_id = id;
      ASSERT_TRUE(s.apply(host_datagram({r, cb})).empty());
    }
    ASSERT_EQ(s.regions().size(), 64u);
    const CigiWeather w = cigi_weather(s, 0.0, 0.0, 1024, 512);
    EXPECT_LE(w.region_samples, 1u << 26);
    EXPECT_GT(w.region_samples, 0u);
    EXPECT_EQ(weather::validate(w.weather), "");
    if (!thin) {
      // the last region holds its centre's texel whole: its layer's 80 %
      const EnvironmentalRegionControl& last = s.regions().at(64).control;
      EXPECT_NEAR(slot_at(w.map, 0, last.lat_deg, last.lon_deg), 0.8f, 1e-6);
    }
  }
}

}  // namespace
}  // namespace cloudsvc::cigi
