// The stochastic tiling of the noise volumes (weather/noise_tiling.h), read as the CPU
// reference reads it (trilinear, repeating: reference::sample_r8_trilinear_repeat): its
// weights cover space, the blend keeps the noise's distribution (so a coverage c still
// covers a fraction c), the field is continuous across cell faces, it does not repeat with
// the volume's period, and the empty-space bound holds over boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "renderer/reference/cloud_morphology.h"
#include "renderer/reference/texture_sampling.h"
#include "weather/noise_tiling.h"
#include "weather/noise_volumes.h"

namespace cloudsvc::reference {
namespace {

const weather::NoiseVolume& base_volume() {
  static const weather::NoiseVolume v = weather::make_base_shape_noise(128, 1);
  return v;
}

const std::uint32_t kSeed = weather::base_tiling_seed(1, weather::CloudType::Stratocumulus);

double untiled(const glm::dvec3& s) { return sample_r8_trilinear_repeat(base_volume(), s); }

double tiled(const glm::dvec3& s, std::uint32_t seed = kSeed) {
  static const double mean = weather::noise_mean(base_volume());
  return weather::tiled_noise(untiled, s, seed, mean);
}

// A random point in a box of 40 periods around a field position of the order of the
// Earth's radius in periods of 12 km (cell indices in the hundreds).
glm::dvec3 random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  return glm::dvec3(530.0 + u(rng), -210.0 + u(rng), 17.0 + u(rng));
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mb += b[i];
  ma /= static_cast<double>(a.size());
  mb /= static_cast<double>(b.size());
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}

TEST(NoiseTiling, WeightsCoverEverySpacePoint) {
  std::mt19937_64 rng(7);
  double least = 1e9, weighted = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 s = random_point(rng);
    double sum = 0.0;
    for (int k = 0; k < weather::kTilingLattices; ++k) {
      const double w = weather::tiling_weight(s - 0.25 * k);
      sum += w;
      weighted += w > 0.0 ? 1.0 : 0.0;
    }
    least = std::min(least, sum);
  }
  std::printf("least weight sum %.4f, lattices with weight per point %.2f\n", least, weighted / n);
  EXPECT_GT(least, 0.003);  // the header's bound: never all four faces at once
  EXPECT_NEAR(weighted / n, 2.15, 0.05);
}

TEST(NoiseTiling, BlendKeepsTheNoiseDistributionSoCoverageHolds) {
  std::mt19937_64 rng(11);
  const int n = 100000;
  std::vector<double> a(n), b(n);
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 s = random_point(rng);
    a[i] = untiled(s);
    b[i] = tiled(s);
  }
  const auto moments = [](const std::vector<double>& x) {
    double m = 0, m2 = 0;
    for (double v : x) m += v, m2 += v * v;
    m /= static_cast<double>(x.size());
    return glm::dvec2(m, std::sqrt(m2 / static_cast<double>(x.size()) - m * m));
  };
  const glm::dvec2 ma = moments(a), mb = moments(b);
  std::printf("mean %.4f -> %.4f, standard deviation %.4f -> %.4f\n", ma.x, mb.x, ma.y, mb.y);
  EXPECT_NEAR(mb.x, ma.x, 0.01);
  EXPECT_NEAR(mb.y / ma.y, 1.0, 0.05);
  // the renderer's threshold for coverage c is the volume's quantile Q(1 - c)
  const Quantiles16 q = value_quantiles(base_volume());
  for (double c : {0.2, 0.5, 0.8}) {
    const double threshold = interpolate_quantile(q, 1.0 - c);
    const double covered = static_cast<double>(std::count_if(b.begin(), b.end(), [&](double v) { return v > threshold; })) / n;
    std::printf("coverage %.1f: tiled noise above Q(1 - c) over %.3f\n", c, covered);
    EXPECT_NEAR(covered, c, 0.03) << c;
  }
}

TEST(NoiseTiling, FieldIsContinuousAcrossCellFaces) {
  // a line through dozens of cells of every lattice, in steps of 1/10000 of a period
  const glm::dvec3 start(530.013, -210.37, 17.71), dir = glm::normalize(glm::dvec3(1.0, 0.31, 0.17));
  const double step = 1e-4;
  double jump_tiled = 0.0, jump_untiled = 0.0;
  double prev_t = tiled(start), prev_u = untiled(start);
  for (int i = 1; i <= 300000; ++i) {
    const glm::dvec3 s = start + dir * (step * i);
    const double t = tiled(s), u = untiled(s);
    jump_tiled = std::max(jump_tiled, std::abs(t - prev_t));
    jump_untiled = std::max(jump_untiled, std::abs(u - prev_u));
    prev_t = t;
    prev_u = u;
  }
  std::printf("largest change per 1e-4 period: tiled %.4f, untiled %.4f\n", jump_tiled, jump_untiled);
  EXPECT_LT(jump_tiled, 4.0 * jump_untiled);  // the blend's gain (<= 2) and its weights' slopes, no jump
  EXPECT_LT(jump_tiled, 0.02);
}

TEST(NoiseTiling, FieldDoesNotRepeatWithThePeriod) {
  std::mt19937_64 rng(13);
  const int n = 20000;
  std::vector<double> ut(n), ut_shifted(n), tt(n), tt_shifted(n);
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 s = random_point(rng), shift(1.0, 0.0, 0.0);
    ut[i] = untiled(s);
    ut_shifted[i] = untiled(s + shift);
    tt[i] = tiled(s);
    tt_shifted[i] = tiled(s + shift);
  }
  const double r_untiled = correlation(ut, ut_shifted), r_tiled = correlation(tt, tt_shifted);
  std::printf("correlation one period apart: untiled %.3f, tiled %.3f\n", r_untiled, r_tiled);
  EXPECT_GT(r_untiled, 0.999);
  EXPECT_LT(std::abs(r_tiled), 0.05);

  // a plane through 6 x 6 periods at 32 px per period, thresholded at coverage 0.5 (a
  // cloud mask): the autocorrelation's periodic peaks (docs/MORPHOLOGY.md)
  const int px = 192;
  const double threshold = interpolate_quantile(value_quantiles(base_volume()), 0.5);
  Field mask_untiled{px, px, std::vector<double>(px * px)}, mask_tiled = mask_untiled;
  const glm::dvec3 origin(530.2, -210.6, 17.3), ex = glm::normalize(glm::dvec3(1.0, 0.2, 0.1)),
                   ey = glm::normalize(glm::cross(glm::dvec3(0.3, 0.1, 1.0), ex));
  for (int y = 0; y < px; ++y)
    for (int x = 0; x < px; ++x) {
      const glm::dvec3 s = origin + (ex * static_cast<double>(x) + ey * static_cast<double>(y)) / 32.0;
      mask_untiled.v[static_cast<std::size_t>(y) * px + x] = untiled(s) > threshold ? 1.0 : 0.0;
      mask_tiled.v[static_cast<std::size_t>(y) * px + x] = tiled(s) > threshold ? 1.0 : 0.0;
    }
  const double peak_untiled = periodic_autocorrelation_peak(mask_untiled, px / 16.0, px / 2.0);
  const double peak_tiled = periodic_autocorrelation_peak(mask_tiled, px / 16.0, px / 2.0);
  std::printf("periodic autocorrelation peak of a coverage-0.5 mask: untiled %.3f, tiled %.3f\n", peak_untiled,
              peak_tiled);
  EXPECT_GT(peak_untiled, 0.3);
  EXPECT_LT(peak_tiled, 0.1);
}

TEST(NoiseTiling, LayerTypesAndNoisesHaveTheirOwnMosaics) {
  using weather::CloudType;
  EXPECT_NE(weather::base_tiling_seed(1, CloudType::Cumulus), weather::base_tiling_seed(1, CloudType::Stratus));
  EXPECT_NE(weather::base_tiling_seed(1, CloudType::Cumulus), weather::detail_tiling_seed(1, CloudType::Cumulus));
  EXPECT_NE(weather::base_tiling_seed(1, CloudType::Cumulus), weather::base_tiling_seed(2, CloudType::Cumulus));
  std::mt19937_64 rng(17);
  std::vector<double> a, b;
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 s = random_point(rng);
    a.push_back(tiled(s, weather::base_tiling_seed(1, CloudType::Cumulus)));
    b.push_back(tiled(s, weather::base_tiling_seed(1, CloudType::Stratus)));
  }
  const double r = correlation(a, b);
  std::printf("correlation of the cumulus and stratus mosaics at the same points: %.3f\n", r);
  EXPECT_LT(std::abs(r), 0.05);
}

TEST(NoiseTiling, BoundHoldsOverBoxes) {
  // boxes of the size the march's long-step probes ask about (a few hundred metres against
  // periods of 4-50 km: 0.002-0.04 periods a side)
  const weather::NoiseMaxPyramid pyramid(base_volume());
  const double mean = weather::noise_mean(base_volume());
  const double threshold = interpolate_quantile(value_quantiles(base_volume()), 0.5);  // coverage 0.5
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int violations = 0, skipped = 0, skipped_untiled = 0;
  const int boxes = 3000;
  for (int i = 0; i < boxes; ++i) {
    const glm::dvec3 lo = random_point(rng);
    const glm::dvec3 size(0.002 + 0.038 * unit(rng), 0.002 + 0.038 * unit(rng), 0.002 + 0.038 * unit(rng));
    const double bound = weather::tiled_max_over(pyramid, lo, lo + size, kSeed, mean);
    double largest = 0.0;
    for (int z = 0; z <= 6; ++z)
      for (int y = 0; y <= 6; ++y)
        for (int x = 0; x <= 6; ++x) largest = std::max(largest, tiled(lo + size * glm::dvec3(x, y, z) / 6.0));
    violations += largest > bound + 1e-12 ? 1 : 0;
    skipped += bound < threshold ? 1 : 0;
    skipped_untiled += pyramid.max_over(lo, lo + size) < threshold ? 1 : 0;
  }
  std::printf("boxes the bound clears at coverage 0.5: %d of %d (untiled noise: %d); %d violations\n", skipped, boxes,
              skipped_untiled, violations);
  EXPECT_EQ(violations, 0);
  // of use to the march's empty-space skipping: the lattices' maxima over the box come from
  // independent parts of the volume, so it clears fewer boxes than the untiled noise's
  // bound (measured 156 against 381; 79 without the weights' ranges)
  EXPECT_GT(skipped, skipped_untiled / 3);
}

}  // namespace
}  // namespace cloudsvc::reference
