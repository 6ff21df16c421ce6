// Forecast bands -> renderer layers (weather/cloud_column.h): the documented mapping, and
// layers the renderer accepts for any column.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "weather/cloud_column.h"
#include "weather/standard_atmosphere.h"

namespace {

using namespace cloudsvc::weather;

BandValues band(double cover, double base_m = NAN, double top_m = NAN) { return {cover, base_m, top_m}; }

Weather with(std::vector<CloudLayer> layers) {
  Weather w;
  w.layers = std::move(layers);
  return w;
}

TEST(CloudColumn, LowMiddleAndHighBandsBecomeTheirCloudTypes) {
  CloudColumn c;
  c[CloudBand::Low] = band(0.4, 900, 1500);
  c[CloudBand::Middle] = band(0.3, 3000, 4000);
  c[CloudBand::High] = band(0.2, 9000, 10000);
  const std::vector<CloudLayer> layers = layers_from_column(c);
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[0].type, CloudType::Stratocumulus);
  EXPECT_EQ(layers[1].type, CloudType::Altocumulus);
  EXPECT_EQ(layers[2].type, CloudType::Cirrus);
  EXPECT_DOUBLE_EQ(layers[0].base_m, 900);
  EXPECT_DOUBLE_EQ(layers[0].top_m, 1500);
  EXPECT_DOUBLE_EQ(layers[1].coverage, 0.3);
  EXPECT_EQ(validate(with(layers)), "");

  // Broken or overcast middle and high cloud is a sheet.
  c[CloudBand::Middle].cover = 0.7;
  c[CloudBand::High].cover = 0.5;
  const std::vector<CloudLayer> sheets = layers_from_column(c);
  EXPECT_EQ(sheets[1].type, CloudType::Altostratus);
  EXPECT_EQ(sheets[2].type, CloudType::Cirrostratus);
}

TEST(CloudColumn, ConvectionMakesCumulusOrCumulonimbus) {
  CloudColumn shallow;
  shallow[CloudBand::Low] = band(0.3, 1000, 1800);
  shallow[CloudBand::Convective] = band(0.25, 1100, 3000);
  std::vector<CloudLayer> layers = layers_from_column(shallow);
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_EQ(layers[0].type, CloudType::Cumulus);
  EXPECT_DOUBLE_EQ(layers[0].coverage, 0.3);

  // A deck with a few embedded cumuli stays stratocumulus.
  shallow[CloudBand::Low].cover = 0.9;
  EXPECT_EQ(layers_from_column(shallow)[0].type, CloudType::Stratocumulus);

  CloudColumn deep;
  deep[CloudBand::Convective] = band(0.3, 800, 11000);
  deep[CloudBand::High] = band(0.2, 9000, 12000);
  layers = layers_from_column(deep);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].type, CloudType::Cumulonimbus);
  EXPECT_DOUBLE_EQ(layers[0].base_m, 800);
  EXPECT_DOUBLE_EQ(layers[0].top_m, 11000);
  // The cirrus (less cover) moves above the cumulonimbus.
  EXPECT_EQ(layers[1].type, CloudType::Cirrus);
  EXPECT_DOUBLE_EQ(layers[1].base_m, 11000);
  EXPECT_DOUBLE_EQ(layers[1].top_m, 12000);
  EXPECT_EQ(validate(with(layers)), "");
}

TEST(CloudColumn, TheWiderLayerKeepsItsAltitudesWhereLayersOverlap) {
  CloudColumn c;
  c[CloudBand::Low] = band(0.85, 1000, 3000);        // a deck
  c[CloudBand::Convective] = band(0.2, 500, 11000);  // towers through it
  const std::vector<CloudLayer> layers = layers_from_column(c);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].type, CloudType::Stratocumulus);
  EXPECT_DOUBLE_EQ(layers[0].base_m, 1000);
  EXPECT_EQ(layers[1].type, CloudType::Cumulonimbus);
  EXPECT_DOUBLE_EQ(layers[1].base_m, 3000);  // rising out of the deck
  EXPECT_DOUBLE_EQ(layers[1].top_m, 11000);
}

TEST(CloudColumn, MissingAltitudesComeFromTheCloudTypeAndClearBandsGiveNoLayer) {
  CloudColumn c;
  c[CloudBand::Middle] = band(0.4);
  c[CloudBand::High] = band(0.005, 9000, 10000);  // below kLeastLayerCover
  c[CloudBand::Low] = band(0.0, 800, 1200);
  std::vector<CloudLayer> layers = layers_from_column(c);
  ASSERT_EQ(layers.size(), 1u);
  const CloudTypeTraits& ac = cloud_type_traits(CloudType::Altocumulus);
  EXPECT_DOUBLE_EQ(layers[0].base_m, ac.default_base_m);
  EXPECT_DOUBLE_EQ(layers[0].top_m, ac.default_top_m);

  // Only a base: the type's default thickness above it. Equal base and top: widened.
  c[CloudBand::Middle] = band(0.4, 3500);
  layers = layers_from_column(c);
  EXPECT_DOUBLE_EQ(layers[0].top_m - layers[0].base_m, ac.default_top_m - ac.default_base_m);
  c[CloudBand::Middle] = band(0.4, 3500, 3500);
  EXPECT_DOUBLE_EQ(layers_from_column(c)[0].top_m, 3500 + kLeastBandThickness_m);

  // Total cover alone (no banded fields) is low cloud at the given cloud base.
  CloudColumn total;
  total[CloudBand::Total] = band(0.6, 700);
  layers = layers_from_column(total);
  ASSERT_EQ(layers.size(), 1u);
  EXPECT_EQ(layers[0].type, CloudType::Stratocumulus);
  EXPECT_DOUBLE_EQ(layers[0].base_m, 700);
}

TEST(CloudColumn, AProfileFillsTheBandsByMaximumOverlap) {
  // Pressure levels every 50 hPa with cloud at 900-850 hPa (low) and 400-350 hPa (high).
  std::vector<ProfileSample> profile;
  for (double hPa = 1000; hPa >= 200; hPa -= 50) {
    double cover = 0.0;
    if (hPa == 900) cover = 0.4;
    if (hPa == 850) cover = 0.7;
    if (hPa == 400 || hPa == 350) cover = 0.3;
    profile.push_back({standard_pressure_altitude_m(hPa * 100), cover});
  }
  CloudColumn c;
  c[CloudBand::High] = band(0.1, 10000, 11000);  // the forecast's own band wins
  fill_bands_from_profile(c, profile);
  EXPECT_DOUBLE_EQ(c[CloudBand::Low].cover, 0.7);
  EXPECT_DOUBLE_EQ(c[CloudBand::Middle].cover, 0.0);
  EXPECT_DOUBLE_EQ(c[CloudBand::High].cover, 0.1);
  const double z900 = standard_pressure_altitude_m(90000), z950 = standard_pressure_altitude_m(95000);
  const double z850 = standard_pressure_altitude_m(85000), z800 = standard_pressure_altitude_m(80000);
  EXPECT_NEAR(c[CloudBand::Low].base_m, z900 - 0.5 * (z900 - z950), 1e-6);
  EXPECT_NEAR(c[CloudBand::Low].top_m, z850 + 0.5 * (z800 - z850), 1e-6);
  EXPECT_GT(low_middle_boundary_m(), 1800.0);
  EXPECT_LT(low_middle_boundary_m(), 2100.0);
  EXPECT_GT(middle_high_boundary_m(), 6000.0);
  EXPECT_LT(middle_high_boundary_m(), 6600.0);
}

TEST(CloudColumn, AnyColumnGivesLayersTheRendererAccepts) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto maybe = [&](double v) { return u(rng) < 0.2 ? NAN : v; };
  for (int i = 0; i < 20000; ++i) {
    CloudColumn c;
    for (BandValues& b : c.bands) {
      const double base = -1000 + 25000 * u(rng);
      b = band(maybe(u(rng) * 1.1 - 0.05), maybe(base), maybe(base + (u(rng) - 0.2) * 12000));
    }
    const std::vector<CloudLayer> layers = layers_from_column(c);
    ASSERT_EQ(validate(with(layers)), "") << "column " << i;
  }
}

}  // namespace
