// The droplets' tabulated Mie phase function (renderer/model/mie_phase_table.h): normalised,
// faithful to the size average it samples, the glory and the fogbow where Lorenz-Mie theory
// puts them for the droplet size, and a sampler that draws the density it claims.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "renderer/model/mie.h"
#include "renderer/model/mie_phase_table.h"
#include "renderer/model/slab_monte_carlo.h"
#include "tests/phase_maxima.h"
#include "tests/sanitizer_build.h"

namespace cloudsvc::model {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Why a test that builds a table may skip in the sanitizer build (tests/sanitizer_build.h).
constexpr const char* kTableBuiltHere = "; MiePhaseTable.AgreesWithAFineSizeAverage builds a table here";

// Before scaling, the interpolated table held all but a fraction of the scattered light,
// and <cos theta> of the table matches the size average's g: the forward peak is resolved.
void expect_normalised_with_resolved_forward_peak(double d) {
  const std::shared_ptr<const PhaseTable> t = mie_phase_table(d);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(t->normalisation[c], 1.0, 2e-3) << "d " << d << " channel " << c;
    double g = 0.0;
    for (int i = 0; i + 1 < kPhaseTableSamples; ++i) {
      const double a = phase_table_angle_deg(i) * kDeg, b = phase_table_angle_deg(i + 1) * kDeg;
      const double m = 0.5 * (a + b);
      g += 2.0 * std::numbers::pi * t->at_angle_deg(m / kDeg)[c] * std::cos(m) * std::sin(m) * (b - a);
    }
    EXPECT_NEAR(g, t->g[c], 3e-3) << "d " << d << " channel " << c;
    std::printf("d %.0f um channel %d: normalisation %.5f, g table %.4f, size average %.4f\n", d, c,
                t->normalisation[c], g, t->g[c]);
  }
  EXPECT_NEAR(t->effective_diameter_um, d * (1.0 + 2.0 * kDropletRelativeSpread * kDropletRelativeSpread), 0.01 * d);
}

TEST(MiePhaseTable, IsNormalisedAndResolvesTheForwardPeak) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers << kTableBuiltHere;
  for (double d : {5.0, 20.0}) expect_normalised_with_resolved_forward_peak(d);
}

// The largest diameter the tables take (50 um, the narrowest forward peak): ~14 s on two
// cores, minutes under AddressSanitizer, so that build leaves it to the optimised one.
TEST(MiePhaseTable, LargestDropletsForwardPeakIsResolved) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers << kTableBuiltHere;
  expect_normalised_with_resolved_forward_peak(50.0);
}

// The table's size step (kPhaseTableSizeStep) against a 10x finer one at 550 nm.
TEST(MiePhaseTable, AgreesWithAFineSizeAverage) {
  const std::shared_ptr<const PhaseTable> t = mie_phase_table(10.0);
  std::vector<double> mu;
  for (int i = 0; i < kPhaseTableSamples; i += 5) mu.push_back(std::cos(phase_table_angle_deg(i) * kDeg));
  DropletSpectrum s;
  s.mean_diameter_um = 10.0;
  s.relative_spread = kDropletRelativeSpread;
  s.wavelength_um = kRenderedWavelengthsUm[1];
  s.m = {kWaterRealIndexRgb[1], kWaterIndex550nm.imag()};
  s.size_parameter_step = 0.01;
  const MieAverage fine = mie_size_average(s, mu, 0);
  double worst = 0.0, worst_deg = 0.0;
  for (std::size_t k = 0; k < mu.size(); ++k) {
    const double rel = std::abs(t->phase[5 * k].g * t->normalisation.g / fine.phase[k] - 1.0);
    if (rel > worst) { worst = rel; worst_deg = phase_table_angle_deg(static_cast<int>(5 * k)); }
  }
  std::printf("table vs size step 0.01: worst relative difference %.4f at %.1f deg\n", worst, worst_deg);
  EXPECT_LT(worst, 0.03);
}

// The glory's first ring: red outside green outside blue, and its radius falls as the
// droplets grow (~1/d); the fogbow 34-41 deg from the antisolar point, wider for larger
// droplets (towards the rainbow's 42 deg).
TEST(MiePhaseTable, GloryAndFogbowFollowTheDropletSize) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers << kTableBuiltHere;
  double ring_green[2] = {0.0, 0.0}, bow_green[2] = {0.0, 0.0};
  const double sizes[2] = {10.0, 20.0};
  for (int k = 0; k < 2; ++k) {
    const std::shared_ptr<const PhaseTable> t = mie_phase_table(sizes[k]);
    double ring[3], bow[3];
    for (int c = 0; c < 3; ++c) {
      ring[c] = test::glory_first_ring_deg(*t, c);
      bow[c] = test::table_maximum_deg(*t, c, 25.0, 48.0);
      std::printf("d %.0f um channel %d: glory first ring %.2f deg; fogbow %.2f deg\n", sizes[k], c, ring[c], bow[c]);
      EXPECT_GT(bow[c], 34.0);
      EXPECT_LT(bow[c], 41.0);
    }
    EXPECT_GT(ring[0], ring[1]);
    EXPECT_GT(ring[1], ring[2]);
    ring_green[k] = ring[1];
    bow_green[k] = bow[1];
  }
  EXPECT_NEAR(ring_green[0] / ring_green[1], 2.0, 0.3);
  EXPECT_GT(bow_green[1], bow_green[0]);
}

// sample_cos draws scattering angles with the density of its channel: the fraction of
// 200 000 draws per channel in each angle bin against the bin's integral of the density.
TEST(MiePhaseTable, SamplerDrawsEachChannelsDensity) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers << kTableBuiltHere;
  const std::shared_ptr<const PhaseTable> t = mie_phase_table(14.0);
  const std::vector<double> edges = {0.0, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 70.0, 100.0, 130.0, 140.0, 150.0, 170.0, 178.0, 180.0};
  const std::size_t bins = edges.size() - 1;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> expected(bins, 0.0), observed(bins, 0.0);
    for (std::size_t b = 0; b < bins; ++b) {
      const int n = 2000;
      for (int i = 0; i < n; ++i) {
        const double a = (edges[b] + (edges[b + 1] - edges[b]) * (i + 0.5) / n) * kDeg;
        expected[b] += 2.0 * std::numbers::pi * t->at_cos(std::cos(a))[c] * std::sin(a) * (edges[b + 1] - edges[b]) * kDeg / n;
      }
    }
    Pcg32 rng(3, 9 + static_cast<std::uint64_t>(c));
    const int draws = 200000;
    for (int i = 0; i < draws; ++i) {
      const double theta = std::acos(t->sample_cos(c, [&] { return rng.uniform(); })) / kDeg;
      for (std::size_t b = 0; b < bins; ++b)
        if (theta >= edges[b] && theta < edges[b + 1]) { observed[b] += 1.0 / draws; break; }
    }
    for (std::size_t b = 0; b < bins; ++b) {
      const double se = std::sqrt(expected[b] * (1.0 - expected[b]) / draws);
      EXPECT_NEAR(observed[b], expected[b], 4.5 * se + 1e-4) << "channel " << c << ", bin " << edges[b] << "-" << edges[b + 1] << " deg";
    }
  }
}

TEST(MiePhaseTable, CachesPerTenthOfAMicrometre) {
  if (test::kSanitizerBuild) GTEST_SKIP() << test::kSlowUnderSanitizers << kTableBuiltHere;
  EXPECT_EQ(mie_phase_table(12.02).get(), mie_phase_table(11.98).get());
  EXPECT_NE(mie_phase_table(12.02).get(), mie_phase_table(12.1).get());
  EXPECT_EQ(mie_phase_table(1.0).get(), mie_phase_table(5.0).get());  // clamped to [5, 50]
}

TEST(MiePhaseTable, AngleBetweenKeepsTinyAndNearlyOppositeAngles) {
  const glm::dvec3 a(0.0, 0.0, 1.0);
  const glm::dvec3 b = glm::normalize(glm::dvec3(1e-9, 0.0, 1.0));
  EXPECT_NEAR(angle_between(a, b), 1e-9, 1e-15);
  EXPECT_NEAR(angle_between(a, -b), std::numbers::pi - 1e-9, 1e-15);
  EXPECT_EQ(cloud_phase_model_from_name("mie"), CloudPhaseModel::kMie);
  EXPECT_EQ(cloud_phase_model_from_name("fit"), CloudPhaseModel::kFit);
  EXPECT_FALSE(cloud_phase_model_from_name("Mie").has_value());
}

}  // namespace
}  // namespace cloudsvc::model
