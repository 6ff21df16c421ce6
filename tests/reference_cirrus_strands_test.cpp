// Cirrus in strands that run east-west (weather/noise_shaping.h, CloudTypeTraits::
// strand_ratio): the shaping matrix itself, and the CPU reference's cirrus field measured
// along and across the strands: its correlation length east-west is several times that
// north-south, where a layer without strands (stratocumulus) is as long as it is wide.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "renderer/reference/cloud_field.h"
#include "renderer/reference/reference_renderer.h"
#include "renderer/reference/reference_scene.h"
#include "weather/noise_shaping.h"

namespace cloudsvc::reference {
namespace {

TEST(NoiseShaping, CirrusStrandsRunEastWestAndOnlyCirrusHasThem) {
  const weather::CloudTypeTraits& ci = weather::cloud_type_traits(weather::CloudType::Cirrus);
  const glm::dmat3 S = weather::noise_shaping(ci);
  EXPECT_GE(ci.strand_ratio, 4.0);
  const double r = ci.strand_ratio;
  for (const double lat : {0.0, 47.45, -60.0, 89.9}) {
    const glm::dmat3 E = geo::enu_to_ecef(lat, 8.0);
    const double c = std::cos(lat * M_PI / 180.0), s_ = std::sin(lat * M_PI / 180.0);
    EXPECT_NEAR(glm::length(S * E[0]), 1.0, 1e-12) << lat;  // east: along the strands
    EXPECT_NEAR(glm::length(S * E[1]), std::sqrt(1.0 + (r * r - 1.0) * c * c), 1e-9) << lat;  // north: across
    EXPECT_NEAR(glm::length(S * E[2]), std::sqrt(1.0 + (r * r - 1.0) * s_ * s_), 1e-9) << lat;  // up
  }
  for (const weather::CloudType t : weather::all_cloud_types()) {
    if (t == weather::CloudType::Cirrus) continue;
    EXPECT_EQ(weather::noise_shaping(weather::cloud_type_traits(t)), glm::dmat3(1.0)) << weather::cloud_type_name(t);
  }
}

// Mean autocorrelation of the extinction along lines in direction `dir` (local ENU,
// horizontal) at the layer's middle, for lags of 0..max_lag steps of step_m: 120 lines
// spread over 60 km.
std::vector<double> autocorrelation(const CloudField& field, const ReferenceScene& s, double alt, glm::dvec3 dir,
                                    double step_m, int samples, int max_lag) {
  const glm::dvec3 normal(-dir.y, dir.x, 0.0);
  std::vector<double> acc(static_cast<size_t>(max_lag) + 1, 0.0);
  double var = 0.0, mean = 0.0;
  std::vector<std::vector<double>> lines;
  std::uint64_t evals = 0;
  for (int l = 0; l < 120; ++l) {
    std::vector<double> v;
    const glm::dvec3 start = normal * (500.0 * l - 30000.0) - dir * (0.5 * step_m * samples);
    for (int i = 0; i < samples; ++i) {
      const glm::dvec3 ground = start + dir * (step_m * i);
      const glm::dvec3 p = ground + s.shell.up_at(ground) * (alt - s.shell.altitude_of(ground));
      v.push_back(field.sample(0, p, s.shell.altitude_of(p), true, evals).sigma_t);
      mean += v.back();
    }
    lines.push_back(std::move(v));
  }
  mean /= 120.0 * samples;
  for (const auto& v : lines)
    for (double x : v) var += (x - mean) * (x - mean);
  var /= 120.0 * samples;
  for (int lag = 0; lag <= max_lag; ++lag) {
    double c = 0.0;
    int n = 0;
    for (const auto& v : lines)
      for (int i = 0; i + lag < samples; ++i, ++n) c += (v[static_cast<size_t>(i)] - mean) * (v[static_cast<size_t>(i + lag)] - mean);
    acc[static_cast<size_t>(lag)] = var > 0.0 ? c / n / var : 0.0;
  }
  return acc;
}

// The first lag (m) at which the autocorrelation falls below 1/2, linear between lags.
double half_length_m(const std::vector<double>& acc, double step_m) {
  for (size_t i = 1; i < acc.size(); ++i)
    if (acc[i] < 0.5) return step_m * (static_cast<double>(i) - (0.5 - acc[i]) / (acc[i - 1] - acc[i]));
  return step_m * static_cast<double>(acc.size());
}

struct StrandCase {
  weather::CloudType type;
  double base_m, top_m;
  double min_ratio, max_ratio;  // east-west over north-south correlation length at 47.45 N
};

class StrandRatio : public ::testing::TestWithParam<StrandCase> {};

TEST_P(StrandRatio, CorrelationLengthAlongTheStrandsOverAcrossThem) {
  const StrandCase c = GetParam();
  weather::Weather w;
  weather::CloudLayer l;
  l.type = c.type;
  l.base_m = c.base_m;
  l.top_m = c.top_m;
  l.coverage = 0.5;
  l.wind = {30.0, 8.0};
  w.layers.push_back(l);
  w.map_seed = 7;
  ViewRequest v;
  v.position = {47.45, 8.0, 500.0};
  v.attitude = {90.0, 0.0, 0.0};
  v.unix_time_s = 1.78e9;
  v.width = 16;
  v.height = 9;
  const ReferenceScene s = make_reference_scene(v, w);  // the wind's anchor: this view
  const auto inputs = reference_inputs(InputConfig{}, w.map_seed);
  const CloudField field(s, *inputs);
  const glm::dvec3 along(1.0, 0.0, 0.0), across(0.0, 1.0, 0.0);  // east, north
  const double alt = 0.5 * (c.base_m + c.top_m), step = 100.0;
  const double len_along = half_length_m(autocorrelation(field, s, alt, along, step, 400, 200), step);
  const double len_across = half_length_m(autocorrelation(field, s, alt, across, step, 400, 200), step);
  const double ratio = len_along / len_across;
  std::printf("%s: correlation half-length east-west %.0f m, north-south %.0f m, ratio %.2f\n",
              std::string(weather::cloud_type_name(c.type)).c_str(), len_along, len_across, ratio);
  EXPECT_GT(ratio, c.min_ratio);
  EXPECT_LT(ratio, c.max_ratio);
}

INSTANTIATE_TEST_SUITE_P(Layers, StrandRatio,
                         ::testing::Values(StrandCase{weather::CloudType::Cirrus, 9000.0, 10000.0, 2.5, 12.0},
                                           StrandCase{weather::CloudType::Stratocumulus, 1200.0, 1800.0, 0.6, 1.6}));

}  // namespace
}  // namespace cloudsvc::reference
