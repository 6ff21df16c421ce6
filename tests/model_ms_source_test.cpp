// The split multiple-scattering model (renderer/model/ms_source_table.h): the peak beam's
// closed forms, the depth coordinate, and the model (peak beam + Monte Carlo diffuse
// source) against the full slab Monte Carlo (slab_monte_carlo.h), which knows nothing of
// the split.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "renderer/model/ms_source_table.h"
#include "renderer/model/slab_flux_table.h"
#include "renderer/model/slab_monte_carlo.h"
#include "renderer/model/slab_renderer_model.h"
#include "tests/sanitizer_build.h"

namespace {

using namespace cloudsvc::model;

constexpr double kDropletUm = 14.0;

// Integral over the sphere of a function of cos theta (Gauss-Legendre would miss the
// diffraction peak; a fine midpoint rule in the variable s = sqrt(1 - mu) resolves it).
template <typename Fn>
double sphere_integral(const Fn& fn) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = std::sqrt(2.0) * (i + 0.5) / n;  // mu = 1 - s^2, dmu = 2 s ds
    const double mu = 1.0 - s * s;
    sum += fn(mu) * 2.0 * s * (std::sqrt(2.0) / n);
  }
  return 2.0 * std::numbers::pi * sum;
}

TEST(PeakBeam, IsSingleScatteringAtTheTopOfTheCloud) {
  const JdDParams p = jdd_params(kDropletUm);
  for (double mu : {-1.0, 0.0, 0.5, 0.99, 1.0})
    EXPECT_NEAR(peak_beam_phase(mu, 0.0, p), jdd_phase(mu, p), 1e-12 * jdd_phase(mu, p));
}

// Each peak scattering keeps the beam's energy: what is left of the peak beam after a
// slant optical depth tau is e^-(1 - f) tau (the delta-scaled beam), f the peak's weight.
TEST(PeakBeam, CarriesTheDeltaScaledBeam) {
  const JdDParams p = jdd_params(kDropletUm);
  const double f = 1.0 - p.w_d;
  for (double tau : {0.0, 0.5, 2.0, 8.0, 20.0}) {
    const double total = sphere_integral([&](double mu) { return peak_beam_phase(mu, tau, p); });
    EXPECT_NEAR(total, std::exp(-(1.0 - f) * tau), 2e-4 * std::exp(-(1.0 - f) * tau)) << "tau " << tau;
  }
}

// Towards the sun the peak beam's diffraction peak broadens and drops with the number of
// peak scatterings.
TEST(PeakBeam, BroadensTowardsTheSunWithDepth) {
  const JdDParams p = jdd_params(kDropletUm);
  const double f = 1.0 - p.w_d;
  const double peak1 = peak_beam_phase(1.0, 1.0, p) / std::exp(-(1.0 - f) * 1.0);
  const double peak8 = peak_beam_phase(1.0, 8.0, p) / std::exp(-(1.0 - f) * 8.0);
  EXPECT_LT(peak8, 0.5 * peak1);
  // broader: at 3 degrees from the sun a larger share of the peak value
  const double c3 = std::cos(3.0 * std::numbers::pi / 180.0);
  EXPECT_GT(peak_beam_phase(c3, 8.0, p) / peak_beam_phase(1.0, 8.0, p),
            2.0 * peak_beam_phase(c3, 1.0, p) / peak_beam_phase(1.0, 1.0, p));
}

// Past peak_beam_cutoff_tau the peak beam is negligible at any depth, for every droplet
// size and scattering angle (checked on a fine grid of depths beyond the cut-off). Away
// from the sun the cut-off comes well before the frame's 12 / w_D: ~8 at 120 degrees for
// 14 um droplets; towards the sun (the diffraction peak, ~1000 sr^-1) it lies beyond it.
TEST(PeakBeam, IsNegligibleBeyondItsViewCutoff) {
  for (double d : {5.0, 14.0, 30.0, 50.0}) {
    const JdDParams p = jdd_params(d);
    std::vector<double> cosines = {std::cos(0.05 * std::numbers::pi / 180.0), std::cos(0.5 * std::numbers::pi / 180.0)};
    for (int i = 0; i <= 160; ++i) cosines.push_back(-1.0 + i / 80.0);
    for (double cos_theta : cosines) {
      const double tau_c = peak_beam_cutoff_tau(cos_theta, p, kPeakBeamNegligible);
      ASSERT_TRUE(std::isfinite(tau_c) && tau_c >= 0.0);
      for (double x = 0.0; x < 40.0; x += 0.25)
        EXPECT_LE(peak_beam_phase(cos_theta, tau_c + x, p), kPeakBeamNegligible * (1.0 + 1e-9))
            << "d " << d << " cos " << cos_theta << " tau_c " << tau_c << " + " << x;
    }
  }
  const JdDParams p = jdd_params(kDropletUm);
  const double back = peak_beam_cutoff_tau(std::cos(120.0 * std::numbers::pi / 180.0), p, kPeakBeamNegligible);
  EXPECT_GT(back, 6.0);
  EXPECT_LT(back, 0.6 * 12.0 / peak_beam_slowest_decay());
  EXPECT_GT(peak_beam_cutoff_tau(1.0, p, kPeakBeamNegligible), 12.0 / peak_beam_slowest_decay());
}

TEST(MsDepthCoordinate, RoundTripsAndIsLogSpacedAtTheBoundaries) {
  for (double tau : {0.01, 1.0, 16.0, 512.0}) {
    for (double y : {0.0, 0.1, 0.25, 0.5, 0.7, 1.0}) {
      const double ta = ms_tau_above(y, tau);
      EXPECT_NEAR(ms_depth_coordinate(ta, tau - ta), y, 1e-9) << "tau " << tau << " y " << y;
    }
    EXPECT_DOUBLE_EQ(ms_depth_coordinate(0.5 * tau, 0.5 * tau), 0.5);
  }
  // In a thick slab the first tenth of y covers about half an optical depth below the top.
  EXPECT_LT(ms_tau_above(0.1, 512.0), 1.5);
  EXPECT_NEAR(ms_depth_coordinate(0.003, 0.007), 0.3, 0.01);  // thin slab: nearly tau_a / tau
}

// The model made of the peak beam and a diffuse source from this slab's own Monte Carlo
// column matches the full Monte Carlo radiances reflected and transmitted, including
// looking at the sun through a thin cloud (the aureole, where orders of scattering
// through the diffraction peak dominate). The earlier two-stream model errs by up to a
// factor 1.8 on these cases.
TEST(MsSourceModel, MatchesTheSlabMonteCarlo) {
  const JdDParams p = jdd_params(kDropletUm);
  const ViewDirection views[] = {{0.0, 0.0}, {60.0, 0.0}, {60.0, 180.0}};
  struct Case {
    double tau, sun;
  };
  // Under AddressSanitizer (~15x slower) the first case only.
  const std::vector<Case> cases = cloudsvc::test::kSanitizerBuild
                                      ? std::vector<Case>{{1.0, 60.0}}
                                      : std::vector<Case>{{1.0, 60.0}, {4.0, 0.0}, {16.0, 60.0}};
  for (const Case& c : cases) {
    const SlabSpec slab = slab_from_optical_depth(c.tau, c.sun, kDropletUm);
    SlabMcOptions mo;
    mo.photons = c.tau > 10.0 ? 200000 : 500000;
    for (const ViewDirection& v : views) mo.views.push_back(v);
    const SlabMcResult mc = run_slab_monte_carlo(slab, mo);
    MsSourceOptions so;
    so.photons = c.tau > 10.0 ? 60000 : 500000;
    so.seed = 7;
    const MsSourceColumn column = compute_ms_source_column(c.tau, std::cos(c.sun * std::numbers::pi / 180.0), p, so);
    EXPECT_EQ(column.lost_photons, 0u);
    SlabRendererModelOptions model = converged_renderer_model_options();
    model.primary_steps = 1024;
    model.ms_source_column = &column;
    for (std::size_t k = 0; k < std::size(views); ++k) {
      for (bool top : {true, false}) {
        const Estimate& e = top ? mc.radiance_top[k] : mc.radiance_bottom[k];
        const double m = slab_renderer_model_radiance(slab, views[k], top, model).radiance;
        std::printf("tau %g sun %g view %g/%g %s: MC %.4g +- %.2g, model %.4g (%+.1f %%)\n", c.tau, c.sun,
                    views[k].zenith_deg, views[k].rel_azimuth_deg, top ? "R" : "T", e.mean, e.std_error, m,
                    100.0 * (m / e.mean - 1.0));
        ASSERT_LT(e.std_error, 0.05 * e.mean);
        EXPECT_NEAR(m / e.mean, 1.0, 0.12) << "tau " << c.tau << " sun " << c.sun << " view " << k
                                           << (top ? " reflected" : " transmitted");
      }
    }
  }
}

// The diffuse table (model::ms_diffuse_incidence_table) against the slab transmittance table,
// an independent Monte Carlo (model::slab_flux_table): the radiance its source sends out of
// the top and the base of a slab lit by unit diffuse flux from above, by the formal
// solution L(mu) = int J(t, mu) e^(-t / mu) dt / mu (t the optical depth from the exit face),
// integrated to fluxes, is the reflected 1 - T(tau) and the diffusely transmitted part of
// T(tau) (T minus the unscattered 2 E_3(tau)), within 5 % (thin slabs reflect up to 8 %
// too much: the kernel that stands in for the diffraction peak, kMsDiffuseIncidenceKernelG, spreads
// light that arrives near the horizon upwards), and the two together conserve energy
// within 2 %. The table has no azimuth dependence.
TEST(MsDiffuseIncidenceTable, ReflectsAndTransmitsTheSlabFluxes) {
  const MsSourceTable& table = ms_diffuse_incidence_table();
  const MsSourceTableShape& shape = table.shape();
  ASSERT_EQ(shape.n_sun, 1);
  const int n_phi = shape.directions.n_phi;
  for (std::size_t i = 0; i < table.values().size(); i += n_phi)
    for (int k = 1; k < n_phi; ++k) ASSERT_EQ(table.values()[i + k], table.values()[i]) << "value " << i;

  const int n_mu = 64, n_t = 1500;
  for (double tau : {0.5, 2.0, 8.0, 30.0, 100.0}) {
    double reflected = 0.0, transmitted = 0.0, unscattered = 0.0;
    for (int m = 0; m < n_mu; ++m) {
      const double mu = (m + 0.5) / n_mu;
      double up = 0.0, down = 0.0;
      const double t_end = std::min(tau, 40.0 * mu), dt = t_end / n_t;
      for (int i = 0; i < n_t; ++i) {
        const double t = (i + 0.5) * dt, w = std::exp(-t / mu) * dt / mu;
        up += w * table.lookup(t, tau - t, 1.0, mu, 0.0);     // leaving the top: t below it
        down += w * table.lookup(tau - t, t, 1.0, -mu, 0.0);  // leaving the base: t above it
      }
      const double d_flux = 2.0 * std::numbers::pi * mu / n_mu;
      reflected += d_flux * up;
      transmitted += d_flux * down;
      unscattered += 2.0 * mu * std::exp(-tau / mu) / n_mu;
    }
    const double T = slab_diffuse_transmittance(tau);
    std::printf("tau %5.1f: reflected %.4f (table 1 - T %.4f), diffusely transmitted %.4f (table %.4f)\n", tau,
                reflected, 1.0 - T, transmitted, T - unscattered);
    EXPECT_NEAR(reflected, 1.0 - T, (tau < 1.0 ? 0.1 : 0.05) * (1.0 - T)) << "tau " << tau;
    EXPECT_NEAR(transmitted, T - unscattered, 0.05 * (T - unscattered)) << "tau " << tau;
    EXPECT_NEAR(reflected + transmitted + unscattered, 1.0, 0.02) << "tau " << tau;
  }
}

}  // namespace
