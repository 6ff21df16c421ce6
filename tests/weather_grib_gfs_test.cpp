// The real GFS forecast in ../shared/data/grib (read in place, never copied): the reader's
// values at grid points against `grib_get -l LAT,LON,1` on the same file, and the layers
// the renderer derives from them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "geodesy/utc_time.h"
#include "weather/gridded_weather.h"
#include "weather/standard_atmosphere.h"

namespace {

namespace fs = std::filesystem;
using namespace cloudsvc::weather;

std::string gfs_file() {
  const fs::path p = fs::path(CLOUDSVC_SHARED_DATA_DIR) / "grib" / "gfs-2p5deg-clouds.grib2";
  return fs::exists(p) ? p.string() : std::string();
}

#define REQUIRE_GFS(var)                                                                         \
  const std::string var = gfs_file();                                                            \
  if (var.empty())                                                                               \
    GTEST_SKIP() << "GFS sample not found under " CLOUDSVC_SHARED_DATA_DIR "/grib (public test " \
                    "data, see ../shared/data/README.md)";

double isa(double pa) { return standard_pressure_altitude_m(pa); }

// Packing precision of the file: cover to 1 %, pressures to ~0.1 Pa (metres: < 1).
constexpr double kCover = 0.006, kMetres = 2.0;

void expect_layer(const CloudLayer& l, CloudType type, double coverage, double base_m, double top_m) {
  EXPECT_EQ(l.type, type) << cloud_type_name(l.type);
  EXPECT_NEAR(l.coverage, coverage, kCover);
  EXPECT_NEAR(l.base_m, base_m, kMetres);
  EXPECT_NEAR(l.top_m, top_m, kMetres);
}

TEST(GfsForecast, ReadsTheCloudFieldsAndTheirValidityTime) {
  REQUIRE_GFS(path);
  const GribReadResult r = read_grib_cloud_fields(path);
  EXPECT_EQ(r.messages, 16);
  EXPECT_EQ(r.clouds.size(), 13u);  // 5 covers, 8 bottom / top pressures
  EXPECT_EQ(r.ignored.size(), 3u);  // temperatures at the cloud tops
  const GriddedWeather w = GriddedWeather::from_messages(r.clouds, path);
  ASSERT_EQ(w.valid_times().size(), 1u);
  // 2011-01-10 12 UTC + 120 h (the end of the 114-120 h averaging period).
  EXPECT_EQ(cloudsvc::geo::format_utc_iso8601(w.valid_times()[0]), "2011-01-15T12:00:00Z");
}

TEST(GfsForecast, LayersAtGridPointsMatchGribGet) {
  REQUIRE_GFS(path);
  const GriddedWeather w = GriddedWeather::load_grib({path});
  const double t = w.valid_times()[0];

  // 47.5N 7.5E: low 36 % at 90694.8-85497.1 Pa, high 50 % at 29350.9-22525.1 Pa.
  std::vector<CloudLayer> l = w.layers_at(47.5, 7.5, t);
  ASSERT_EQ(l.size(), 2u);
  expect_layer(l[0], CloudType::Stratocumulus, 0.36, isa(90694.8), isa(85497.1));
  expect_layer(l[1], CloudType::Cirrostratus, 0.50, isa(29350.9), isa(22525.1));

  // 0N 0E: high 14 % at 12990.4-10030.4 Pa only.
  l = w.layers_at(0.0, 0.0, t);
  ASSERT_EQ(l.size(), 1u);
  expect_layer(l[0], CloudType::Cirrus, 0.14, isa(12990.4), isa(10030.4));

  // 22.5N 135E: low 86 % (89050.3-68074.5 Pa), middle 6 % (60340.4-48285.4), high 46 %
  // (14663.4-9903), convective 67 % from 95372.8 to 21814.2 Pa: deep convection. The deck
  // keeps its altitudes, the cumulonimbus rises from its top, the middle cloud inside the
  // cumulonimbus's range has no room.
  l = w.layers_at(22.5, 135.0, t);
  ASSERT_EQ(l.size(), 3u);
  expect_layer(l[0], CloudType::Stratocumulus, 0.86, isa(89050.3), isa(68074.5));
  expect_layer(l[1], CloudType::Cumulonimbus, 0.67, isa(68074.5), isa(21814.2));
  expect_layer(l[2], CloudType::Cirrus, 0.46, isa(14663.4), isa(9903.0));
}

TEST(GfsForecast, BetweenGridPointsTheFieldsAreBilinear) {
  REQUIRE_GFS(path);
  const GriddedWeather w = GriddedWeather::load_grib({path});
  const double t = w.valid_times()[0];
  // Low cover at 47.5N 7.5E, 47.5N 10E, 50N 7.5E, 50N 10E: 36, 41, 48, 77 %.
  EXPECT_NEAR(w.column_at(48.75, 8.75, t)[CloudBand::Low].cover, (0.36 + 0.41 + 0.48 + 0.77) / 4, kCover);
  EXPECT_NEAR(w.column_at(47.5, 8.75, t)[CloudBand::Low].cover, (0.36 + 0.41) / 2, kCover);
}

TEST(GfsForecast, NoSeamAtTheAntimeridianOrThePoles) {
  REQUIRE_GFS(path);
  const GriddedWeather w = GriddedWeather::load_grib({path});
  const double t = w.valid_times()[0];
  for (double lat : {-60.0, -12.3, 0.0, 33.3, 71.0}) {
    const CloudColumn east = w.column_at(lat, 179.9999, t), west = w.column_at(lat, -179.9999, t);
    for (int b = 0; b < kColumnBands; ++b) {
      if (std::isnan(east.bands[b].cover)) continue;
      EXPECT_NEAR(east.bands[b].cover, west.bands[b].cover, 1e-4) << lat << " band " << b;
    }
  }
  for (double pole : {-90.0, 90.0}) {
    const double at0 = w.column_at(pole, 0.0, t)[CloudBand::Low].cover;
    for (double lon : {45.0, 170.0, -100.0}) EXPECT_DOUBLE_EQ(w.column_at(pole, lon, t)[CloudBand::Low].cover, at0);
  }
}

}  // namespace
