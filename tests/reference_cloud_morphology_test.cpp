// Cloud morphology metrics (renderer/reference/cloud_morphology.h) on fields whose answer
// is known: the perimeter-area dimension of smooth (D = 1) and space-filling (D = 2)
// outlines, a power-law size distribution, a tiled vs a non-repeating field's
// autocorrelation, and spectra of known slope.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/fourier_transform.h"
#include "renderer/reference/reference_inputs.h"
#include "weather/cloud_layer.h"
#include "weather/presets.h"

namespace cloudsvc::reference {
namespace {

Field blank(int w, int h) { return Field{w, h, std::vector<double>(static_cast<std::size_t>(w) * h, 0.0)}; }
void fill_rect(Field& f, int x0, int y0, int w, int h, double v = 1.0) {
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) f.v[static_cast<std::size_t>(y) * f.width + x] = v;
}

// A deterministic uniform number in [0, 1) from an index (SplitMix64).
double uniform(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

TEST(CloudMorphology, CloudsAreFourConnectedWithEdgePerimeters) {
  Field f = blank(20, 10);
  fill_rect(f, 2, 2, 3, 3);   // 9 px, perimeter 12
  fill_rect(f, 5, 5, 1, 1);   // touches the square only diagonally: a separate cloud of 1 px
  fill_rect(f, 15, 0, 4, 2);  // touches the border
  const std::vector<CloudObject> c = cloud_objects(f);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].area_px, 8);  // scan order: the border cloud's first row comes first
  EXPECT_EQ(c[0].perimeter_px, 12);
  EXPECT_TRUE(c[0].touches_border);
  EXPECT_EQ(c[1].area_px, 9);
  EXPECT_EQ(c[1].perimeter_px, 12);
  EXPECT_FALSE(c[1].touches_border);
  EXPECT_EQ(c[2].area_px, 1);
  EXPECT_EQ(c[2].perimeter_px, 4);
}

TEST(CloudMorphology, PerimeterAreaDimensionOfSmoothAndSpaceFillingOutlines) {
  Field squares = blank(200, 60);
  int x = 1;
  for (int s : {4, 6, 9, 13, 18, 25, 30}) {
    fill_rect(squares, x, 1, s, s);
    x += s + 2;
  }
  const PowerLawFit smooth = perimeter_area_dimension(cloud_objects(squares));
  EXPECT_EQ(smooth.n, 7);
  EXPECT_NEAR(smooth.exponent, 1.0, 1e-9);  // P = 4 sqrt(A)

  Field lines = blank(120, 40);
  int y = 1;
  for (int len : {10, 20, 40, 80, 110}) {  // 1 px wide: P = 2 A + 2 -> D -> 2
    fill_rect(lines, 1, y, len, 1);
    y += 3;
  }
  const PowerLawFit filling = perimeter_area_dimension(cloud_objects(lines));
  EXPECT_EQ(filling.n, 5);
  EXPECT_NEAR(filling.exponent, 2.0, 0.1);  // 1.93: the two end edges of each line (P = 2 A + 2)
  EXPECT_GT(filling.r2, 0.99);

  // clouds under the minimum area or on the border are left out
  Field small = blank(30, 30);
  fill_rect(small, 1, 1, 3, 3);      // 9 px < 10
  fill_rect(small, 0, 10, 5, 5);     // on the border
  EXPECT_EQ(perimeter_area_dimension(cloud_objects(small)).n, 0);
  EXPECT_TRUE(std::isnan(perimeter_area_dimension(cloud_objects(small)).exponent));
}

TEST(CloudMorphology, PowerLawSizeDistributionIsRecovered) {
  for (double b : {0.8, 1.5}) {
    std::vector<CloudObject> clouds;
    for (int i = 0; i < 4000; ++i) {  // A = A_min u^(-1/b): P(A' > A) = (A / A_min)^(-b)
      CloudObject c;
      c.area_px = static_cast<long>(std::floor(10.0 * std::pow(1.0 - uniform(i + 7919 * static_cast<int>(b * 10)), -1.0 / b)));
      c.perimeter_px = 4;
      clouds.push_back(c);
    }
    const PowerLawFit fit = cloud_size_exponent(clouds);
    EXPECT_NEAR(fit.exponent, b, 0.12 * b) << b;
  }
}

TEST(CloudMorphology, TiledFieldsShowAPeriodicPeakAndRandomOnesDoNot) {
  const int n = 128;
  Field tiled = blank(n, n), scattered = blank(n, n);
  for (int ty = 0; ty < 16; ++ty)
    for (int tx = 0; tx < 16; ++tx) fill_rect(tiled, tx * 8 + 2, ty * 8 + 3, 4, 3);  // period 8 px
  for (int i = 0; i < 256; ++i) {  // the same blobs at random places
    const int x0 = static_cast<int>(uniform(2 * i) * (n - 4)), y0 = static_cast<int>(uniform(2 * i + 1) * (n - 3));
    fill_rect(scattered, x0, y0, 4, 3);
  }
  const double p_tiled = periodic_autocorrelation_peak(tiled, n / 16.0, n / 2.0);
  const double p_scattered = periodic_autocorrelation_peak(scattered, n / 16.0, n / 2.0);
  std::printf("periodic autocorrelation peak: tiled %.3f, scattered %.3f\n", p_tiled, p_scattered);
  EXPECT_GT(p_tiled, 0.5);
  EXPECT_LT(p_scattered, 0.15);
  EXPECT_EQ(periodic_autocorrelation_peak(blank(32, 32), 2.0, 16.0), 0.0);  // constant: no structure
}

TEST(FourierTransform, FindsATonesFrequencyAndInvertsExactly) {
  const std::size_t n = 64;
  std::vector<std::complex<double>> a(n), original(n);
  for (std::size_t j = 0; j < n; ++j) a[j] = original[j] = std::cos(2.0 * std::numbers::pi * 5.0 * j / n) + uniform(j) * 1e-3;
  fourier_transform(a, false);
  // a cosine of 5 cycles: N/2 at k = 5 and k = N - 5, the noise's share elsewhere
  EXPECT_NEAR(std::abs(a[5]), n / 2.0, 0.05);
  EXPECT_NEAR(std::abs(a[n - 5]), n / 2.0, 0.05);
  EXPECT_LT(std::abs(a[7]), 0.05);
  fourier_transform(a, true);
  for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(std::abs(a[j] - original[j]), 0.0, 1e-12);
  EXPECT_EQ(next_power_of_two(1), 1u);
  EXPECT_EQ(next_power_of_two(570), 1024u);
  std::vector<std::complex<double>> odd(12);
  EXPECT_THROW(fourier_transform(odd, false), std::invalid_argument);
}

// The peak from transforms equals its definition summed lag by lag (a field of odd, unequal
// sides, so padding and the overlap counts are exercised).
TEST(CloudMorphology, AutocorrelationPeakMatchesItsDefinitionSummedDirectly) {
  const int w = 37, h = 23;
  Field f = blank(w, h);
  for (std::size_t i = 0; i < f.v.size(); ++i) f.v[i] = uniform(1000 + i) + 0.5 * std::sin(0.9 * static_cast<double>(i % w));
  const double r_min = 2.0, r_max = 11.5;
  double mean = 0.0, var = 0.0;
  for (double v : f.v) mean += v;
  mean /= static_cast<double>(f.v.size());
  for (double v : f.v) var += (v - mean) * (v - mean);
  var /= static_cast<double>(f.v.size());
  std::map<int, std::vector<double>> ring;
  std::vector<std::pair<int, double>> lags;
  for (int dy = 0; dy <= 11; ++dy)
    for (int dx = -11; dx <= 11; ++dx) {
      if (dy == 0 && dx <= 0) continue;
      const double r = std::hypot(dx, dy);
      if (r < r_min || r > r_max) continue;
      double s = 0.0;
      long n = 0;
      for (int y = 0; y + dy < h; ++y)
        for (int x = std::max(0, -dx); x < w && x + dx < w; ++x, ++n) s += (f.at(x, y) - mean) * (f.at(x + dx, y + dy) - mean);
      const int ri = static_cast<int>(std::lround(r));
      ring[ri].push_back(s / static_cast<double>(n) / var);
      lags.emplace_back(ri, s / static_cast<double>(n) / var);
    }
  double expected = 0.0;
  for (const auto& [ri, acf] : lags) {
    std::vector<double> v = ring[ri];
    std::sort(v.begin(), v.end());
    const double median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    expected = std::max(expected, acf - median);
  }
  EXPECT_GT(expected, 0.05);  // the sine's rows give the field a structure to find
  EXPECT_NEAR(periodic_autocorrelation_peak(f, r_min, r_max), expected, 1e-12);
}

TEST(CloudMorphology, RowSpectrumSlopeIsRecovered) {
  const int w = 256, h = 48;
  for (double beta : {-5.0 / 3.0, -3.0}) {
    Field f = blank(w, h);
    for (int y = 0; y < h; ++y)
      for (int k = 1; k < w / 2; ++k) {  // amplitude k^(beta / 2), random phase, periodic in the row
        const double a = std::pow(k, beta / 2.0), phase = 2.0 * std::numbers::pi * uniform(static_cast<std::uint64_t>(y) * w + k);
        for (int x = 0; x < w; ++x) f.v[static_cast<std::size_t>(y) * w + x] += a * std::cos(2.0 * std::numbers::pi * k * x / w + phase);
      }
    // pixels of 50 m: wavelengths 0.5-8 km are k = 1.6-25.6
    const PowerLawFit fit = row_energy_spectrum_slope(f, 50.0, 500.0, 8000.0);
    EXPECT_EQ(fit.n, 24);
    // the Hann window leaks the strongest (lowest) wavenumbers into their neighbours, which
    // steepens steep spectra a little (-3 comes out -3.18)
    EXPECT_NEAR(fit.exponent, beta, beta < -2.0 ? 0.25 : 0.1) << beta;
  }
}

// The cloud fraction by altitude, from the density field: a cumulus layer tapers towards
// its top (its height profile's top ramp), so its "anvil ratio" is well below 1; an
// overcast stratus sheet is cloud at every height (ratio 1).
TEST(CloudMorphology, AnvilRatioFollowsTheLayersVerticalProfile) {
  struct Case {
    weather::CloudType type;
    double coverage, lo, hi;
  };
  for (const Case& c : {Case{weather::CloudType::Cumulus, 0.5, 0.0, 0.8}, Case{weather::CloudType::Stratus, 1.0, 0.95, 1.05}}) {
    weather::Weather w;
    weather::CloudLayer l = weather::default_layer(c.type);
    l.base_m = 1000.0;
    l.top_m = 2500.0;
    l.coverage = c.coverage;
    w.layers.push_back(l);
    w.map_seed = 11;
    ViewRequest v;
    v.position = {47.4, 8.5, 8000.0};
    v.attitude = {0.0, -90.0, 0.0};
    v.unix_time_s = *geo::parse_utc_iso8601("2026-06-21T10:00:00Z");
    v.width = v.height = 64;
    const ReferenceScene scene = make_reference_scene(v, w);
    const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
    const CloudField field(scene, *inputs);
    const double sigma_min = 0.05 * scene.layers[0].density_scale * scene.layers[0].sigma_max_per_m;
    const AnvilRatio a = anvil_ratio(scene, field, 0, 10000.0, 250.0, sigma_min);
    std::printf("type %d: cloud fraction at mid-height %.3f, top fifth %.3f, ratio %.2f\n", static_cast<int>(c.type),
                a.mid_fraction, a.top_fraction, a.ratio);
    EXPECT_GT(a.mid_fraction, 0.1);
    EXPECT_GE(a.ratio, c.lo);
    EXPECT_LE(a.ratio, c.hi);
  }
}

// The cumulonimbus preset's towers spread into anvils under the layer top (weather::Anvil),
// at places the morphology benchmark does not use. The weather map decides how many cells
// reach the top (its type channel; elsewhere they stop as towering cumulus): where the
// towers alone fill the top fifth about as much as mid-height, the anvil makes the top
// fifth's cloud fraction at least twice mid-height's (the target); wherever
// towers reach the band, it at least doubles their area there (or closes the shield);
// below the band nothing changes.
TEST(CloudMorphology, CumulonimbusTowersSpreadIntoAnvils) {
  const weather::Weather w = *weather::preset("cumulonimbus");
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  struct Place {
    double lat, lon;
    const char* time;
  };
  int full_depth_places = 0;
  for (const Place& p : {Place{27.5, -81.0, "2026-07-15T19:00:00Z"}, Place{-2.0, 23.0, "2026-03-10T13:00:00Z"},
                         Place{35.0, -97.0, "2026-05-20T22:00:00Z"}, Place{12.0, 105.0, "2026-08-01T08:00:00Z"}}) {
    ViewRequest v;
    v.position = {p.lat, p.lon, 20000.0};
    v.attitude = {0.0, -90.0, 0.0};
    v.unix_time_s = *geo::parse_utc_iso8601(p.time);
    v.width = v.height = 64;
    ReferenceScene scene = make_reference_scene(v, w);
    const int cb = 1;
    ASSERT_EQ(w.layers[cb].type, weather::CloudType::Cumulonimbus);
    const double sigma_min = 0.05 * scene.layers[cb].density_scale * scene.layers[cb].sigma_max_per_m;
    const AnvilRatio with = anvil_ratio(scene, CloudField(scene, *inputs), cb, 25000.0, 250.0, sigma_min);
    scene.layers[cb].anvil.spread = 0.0f;
    const AnvilRatio towers = anvil_ratio(scene, CloudField(scene, *inputs), cb, 25000.0, 250.0, sigma_min);
    std::printf("%.1f, %.1f: mid-height %.3f, top fifth %.3f (towers alone %.3f): anvil ratio %.2f (towers alone %.2f)\n",
                p.lat, p.lon, with.mid_fraction, with.top_fraction, towers.top_fraction, with.ratio, towers.ratio);
    ASSERT_GT(with.mid_fraction, 0.02) << "a place with cumulonimbus";
    EXPECT_DOUBLE_EQ(with.mid_fraction, towers.mid_fraction) << "the anvil is confined to the layer's top";
    ASSERT_GT(towers.top_fraction, 0.02) << "some towers reach the anvil's band";
    EXPECT_GE(with.top_fraction, std::min(2.0 * towers.top_fraction, 0.9));
    if (towers.ratio >= 0.8) {
      ++full_depth_places;
      EXPECT_GE(with.ratio, 2.0);
    }
  }
  EXPECT_GE(full_depth_places, 2);
}

}  // namespace
}  // namespace cloudsvc::reference
