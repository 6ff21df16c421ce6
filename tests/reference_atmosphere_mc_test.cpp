// Known-answer checks of the clear-sky Monte Carlo path tracer
// (renderer/reference/atmosphere_monte_carlo.h) before it is used to judge the renderer
// (tests/accuracy_atmosphere_mc_test.cpp): phase sampling, majorant bounds, ratio-tracking
// transmittance against the integrated optical depth, a white furnace (no absorption,
// albedo 1, isotropic light at the top: radiance 1 everywhere), single scattering against
// the deterministic integral of reference_atmosphere.h, independence of the thread count,
// and the optically thin limit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "renderer/reference/atmosphere_monte_carlo.h"
#include "renderer/reference/reference_atmosphere.h"

namespace cloudsvc::reference {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

glm::dvec3 direction(double azimuth_deg, double elevation_deg) {
  const double el = elevation_deg * kDeg, az = azimuth_deg * kDeg;
  return {std::cos(el) * std::sin(az), std::cos(el) * std::cos(az), std::sin(el)};
}

TEST(AtmosphereMonteCarlo, PhaseSamplersReproduceTheirMoments) {
  model::Pcg32 rng(7, 1);
  const int n = 400000;
  double r1 = 0, r2 = 0, c1 = 0, c2 = 0;
  for (int i = 0; i < n; ++i) {
    const double mr = mc::sample_rayleigh_cos(rng.uniform());
    r1 += mr, r2 += mr * mr;
    const double mcs = mc::sample_cornette_shanks_cos(atmo::kMieG, rng);
    c1 += mcs, c2 += mcs * mcs;
  }
  // exact moments of the phase functions: midpoint rule over mu with 2e5 nodes
  double norm_r = 0, norm_c = 0, e1 = 0, e2 = 0;
  const int m = 200000;
  for (int i = 0; i < m; ++i) {
    const double mu = -1.0 + (i + 0.5) * 2.0 / m, w = 2.0 * kPi * 2.0 / m;
    norm_r += w * mc::rayleigh_phase(mu);
    const double p = w * mc::cornette_shanks_phase(mu, atmo::kMieG);
    norm_c += p, e1 += p * mu, e2 += p * mu * mu;
  }
  EXPECT_NEAR(norm_r, 1.0, 1e-9);
  EXPECT_NEAR(norm_c, 1.0, 1e-6);
  // sampling error of a mean of n values in [-1, 1]: < 1 / sqrt(n) = 1.6e-3; 4 sigma
  EXPECT_NEAR(r1 / n, 0.0, 4.0 * std::sqrt(0.4 / n));
  EXPECT_NEAR(r2 / n, 0.4, 4.0 * std::sqrt(0.11 / n));
  EXPECT_NEAR(c1 / n, e1, 4.0 * std::sqrt((e2 - e1 * e1) / n));
  EXPECT_NEAR(c2 / n, e2, 4.0 / std::sqrt(n));
  std::printf("Cornette-Shanks g = %.2f: <mu> = %.5f (exact %.5f), <mu^2> = %.5f (exact %.5f)\n", atmo::kMieG,
              c1 / n, e1, c2 / n, e2);
}

TEST(AtmosphereMonteCarlo, BandMajorantsBoundTheExtinction) {
  const mc::McAtmosphere a;
  for (int c = 0; c < 3; ++c)
    for (int b = 0; b < mc::majorant_band_count(); ++b) {
      const double a0 = mc::majorant_band_bottom(b), a1 = mc::majorant_band_bottom(b + 1);
      const double maj = mc::band_majorant(a, c, b);
      for (int i = 0; i <= 1000; ++i) {
        const double alt = a0 + (a1 - a0) * i / 1000.0;
        ASSERT_LE(mc::extinction_at(a, c, alt), maj) << c << " " << alt;
        // the deterministic reference's medium is the same definition
        if (alt < atmo::kThickness) {
          EXPECT_NEAR(mc::extinction_at(a, c, alt), atmo::medium_at(alt).extinction[c], 1e-18);
        }
      }
    }
}

TEST(AtmosphereMonteCarlo, RatioTrackingTransmittanceMatchesTheIntegratedOpticalDepth) {
  const mc::McAtmosphere a;
  model::Pcg32 rng(11, 3);
  for (double mu : {1.0, 0.5, 0.1, 0.03, -0.02}) {
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3 T_ref = atmo::transmittance_to_space(500.0, mu, 20.0);
      const int n = 20000;
      double s = 0, s2 = 0;
      for (int i = 0; i < n; ++i) {
        const double T = mc::sun_transmittance_ratio_tracking(a, c, 500.0, mu, rng);
        s += T, s2 += T * T;
      }
      const double mean = s / n, se = std::sqrt(std::max(0.0, s2 / n - mean * mean) / n);
      EXPECT_NEAR(mean, T_ref[c], 4.0 * se + 1e-12) << "mu " << mu << " channel " << c;
    }
  }
}

// No absorption (aerosol extinction = scattering, no ozone), ground albedo 1, no sun,
// isotropic radiance 1 entering at the top: every direction, up or down, sees radiance 1.
TEST(AtmosphereMonteCarlo, WhiteFurnaceIsOne) {
  mc::McAtmosphere a;
  a.mie_extinction = a.mie_scattering;
  a.ozone_absorption = glm::dvec3(0.0);
  a.ground_albedo = glm::dvec3(1.0);
  a.sun_irradiance = 0.0;
  a.top_radiance = 1.0;
  mc::McSettings s;
  s.paths = 4000;
  for (const glm::dvec3& d : {direction(0, 90), direction(30, 5), direction(200, 0.5), direction(90, -20)}) {
    const mc::McEstimate e = mc::sky_radiance(a, 500.0, d, direction(0, 30), 2, s);
    EXPECT_NEAR(e.total.mean, 1.0, 4.0 * e.total.std_error + 1e-12) << d.x << " " << d.y << " " << d.z;
    EXPECT_LT(e.total.std_error, 0.02);
    std::printf("furnace (%.3f, %.3f, %.3f): %.5f +- %.5f\n", d.x, d.y, d.z, e.total.mean, e.total.std_error);
  }
}

// Single scattering only (max_order 1) against atmo::integrate_inscatter without Psi_ms
// (deterministic quadrature, integrated sun transmittance), noon and low sun.
TEST(AtmosphereMonteCarlo, SingleScatteringMatchesTheDeterministicIntegral) {
  const mc::McAtmosphere a;
  mc::McSettings s;
  s.paths = 20000;
  s.max_order = 1;
  const double r0 = atmo::radius_for_altitude(500.0);
  for (double sun_el : {62.0, 3.0}) {
    const glm::dvec3 sun = direction(180, sun_el);
    for (const glm::dvec3& d : {direction(0, 90), direction(180, 5), direction(0, 5)}) {
      const auto T = [](double alt, double mu) { return atmo::transmittance_to_space(alt, mu, 100.0); };
      const auto none = [](double, double) { return glm::dvec3(0.0); };
      const atmo::RayInscatter ref =
          atmo::integrate_inscatter(r0, d, sun, atmo::path_length(r0, d.z), false, 50.0, 2000.0, T, none);
      for (int c = 0; c < 3; ++c) {
        const mc::McEstimate e = mc::sky_radiance(a, 500.0, d, sun, c, s);
        EXPECT_NEAR(e.total.mean, ref.radiance[c], 4.0 * e.total.std_error) << sun_el << " " << d.z << " " << c;
        EXPECT_LT(e.total.std_error, 0.015 * ref.radiance[c]);
        std::printf("sun %4.1f view z %.3f ch %d: MC %.6e +- %.1e, integral %.6e (%+.2f sigma)\n", sun_el, d.z, c,
                    e.total.mean, e.total.std_error, ref.radiance[c],
                    (e.total.mean - ref.radiance[c]) / e.total.std_error);
      }
    }
  }
}

// An estimate depends on the seed, not on the thread count: bit-identical for 1, 2 and 5
// threads and for all cores (threads = 0); 1000 paths = 7 full chunks and a partial one.
TEST(AtmosphereMonteCarlo, IdenticalForAnyThreadCount) {
  const mc::McAtmosphere a;
  mc::McSettings s;
  s.paths = 1000;
  const glm::dvec3 sun = direction(180, 10), d = direction(30, 15);
  s.threads = 1;
  const mc::McEstimate one = mc::sky_radiance(a, 500.0, d, sun, 1, s);
  EXPECT_EQ(one.paths, 1000);
  for (int threads : {2, 5, 0}) {
    s.threads = threads;
    const mc::McEstimate e = mc::sky_radiance(a, 500.0, d, sun, 1, s);
    EXPECT_EQ(e.total.mean, one.total.mean) << threads;
    EXPECT_EQ(e.total.std_error, one.total.std_error) << threads;
    EXPECT_EQ(e.single.mean, one.single.mean) << threads;
    EXPECT_EQ(e.multiple.mean, one.multiple.mean) << threads;
    EXPECT_EQ(e.multiple.std_error, one.multiple.std_error) << threads;
  }
  s.threads = 1;
  s.seed = 2;
  EXPECT_NE(mc::sky_radiance(a, 500.0, d, sun, 1, s).total.mean, one.total.mean);
}

// Optically thin limit, black ground: multiple / single scattering shrinks in proportion
// to the optical depth (here 100x thinner air: the ratio falls ~100x).
TEST(AtmosphereMonteCarlo, ThinLimitIsSingleScattering) {
  mc::McAtmosphere a;
  a.ground_albedo = glm::dvec3(0.0);
  mc::McSettings s;
  s.paths = 6000;
  const glm::dvec3 sun = direction(180, 30), d = direction(0, 20);
  const mc::McEstimate full = mc::sky_radiance(a, 500.0, d, sun, 2, s);
  a.rayleigh_scattering *= 0.01;
  a.mie_scattering *= 0.01;
  a.mie_extinction *= 0.01;
  a.ozone_absorption *= 0.01;
  const mc::McEstimate thin = mc::sky_radiance(a, 500.0, d, sun, 2, s);
  const double q_full = full.multiple.mean / full.single.mean, q_thin = thin.multiple.mean / thin.single.mean;
  std::printf("multiple / single: %.4f (model air), %.6f (air x 0.01)\n", q_full, q_thin);
  EXPECT_GT(q_full, 0.05);
  EXPECT_GT(q_thin, 0.003 * q_full);
  EXPECT_LT(q_thin, 0.03 * q_full);
}

}  // namespace
}  // namespace cloudsvc::reference
