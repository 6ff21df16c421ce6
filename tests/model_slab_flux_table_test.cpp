// The slab transmittance table (renderer/model/slab_flux_table.h) against fresh Monte
// Carlo runs of the slab solver between its nodes and beyond its last one, and its limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "renderer/model/ms_source_table.h"
#include "renderer/model/slab_flux_table.h"
#include "renderer/model/slab_monte_carlo.h"

namespace cloudsvc::model {
namespace {

Estimate monte_carlo_transmittance(double tau, double mu0, std::uint64_t photons, std::uint64_t seed) {
  SlabMcOptions o;
  o.photons = photons;
  o.seed = seed;
  o.ddis_probability = 0.0;
  const SlabMcResult r =
      run_slab_monte_carlo(slab_from_optical_depth(tau, std::acos(mu0) * 180.0 / std::numbers::pi, kMsTableDropletUm), o);
  return r.transmitted;
}

// Between the nodes in optical depth and sun cosine, and beyond the last node (the
// diffusion limit): the table within 3 % plus 3 standard errors of a Monte Carlo run with
// other random numbers than the table's.
TEST(SlabFluxTable, BeamTransmittanceMatchesTheMonteCarloBetweenNodes) {
  struct Case {
    double tau, mu;
  };
  std::vector<Case> cases = {{300.0, 0.5}};  // beyond the last node
  for (double tau : {0.4, 3.0, 24.0, 90.0})
    for (double mu : {0.12, 0.33, 0.77}) cases.push_back({tau, mu});
  std::uint64_t seed = 99;
  for (const Case& c : cases) {
    const Estimate mc = monte_carlo_transmittance(c.tau, c.mu, c.tau > 100.0 ? 40000 : 20000, seed++);
    const double t = slab_beam_transmittance(c.tau, c.mu);
    EXPECT_NEAR(t, mc.mean, 0.03 * mc.mean + 3.0 * mc.std_error) << "tau " << c.tau << " mu0 " << c.mu;
  }
}

// Diffuse light: 2 int T(mu) mu dmu of fresh Monte Carlo runs (8-point Gauss-Legendre in
// mu), the same tolerance.
TEST(SlabFluxTable, DiffuseTransmittanceMatchesTheMonteCarloBetweenNodes) {
  const double x[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355, 0.4082826787521751,
                       0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681};
  const double w[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436, 0.1813418916891810,
                       0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881};
  std::uint64_t seed = 500;
  for (double tau : {0.7, 12.0, 48.0, 200.0}) {
    double mean = 0.0, var = 0.0;
    for (int k = 0; k < 8; ++k) {
      const Estimate e = monte_carlo_transmittance(tau, x[k], 10000, seed++);
      mean += 2.0 * w[k] * x[k] * e.mean;
      var += std::pow(2.0 * w[k] * x[k] * e.std_error, 2);
    }
    EXPECT_NEAR(slab_diffuse_transmittance(tau), mean, 0.03 * mean + 3.0 * std::sqrt(var)) << "tau " << tau;
  }
}

// No cloud lets everything through; thicker slabs less; a higher sun more through a
// thick slab (its light goes deeper); the pieces of the interpolation meet at the table's
// first and last nodes; the diffuse column is the beam's cosine-weighted mean.
TEST(SlabFluxTable, LimitsMonotonyAndContinuity) {
  EXPECT_DOUBLE_EQ(slab_beam_transmittance(0.0, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(slab_diffuse_transmittance(0.0), 1.0);
  for (double mu : {0.05, 0.3, 1.0}) {
    double prev = 1.0;
    for (double tau = 0.01; tau < 5000.0; tau *= 1.1) {
      const double t = slab_beam_transmittance(tau, mu);
      EXPECT_LE(t, prev + 1e-6) << "tau " << tau << " mu0 " << mu;
      EXPECT_GT(t, 0.0);
      prev = t;
    }
  }
  for (double tau : {8.0, 64.0, 1000.0}) EXPECT_LT(slab_beam_transmittance(tau, 0.2), slab_beam_transmittance(tau, 0.9));
  const double tau_max = kSlabFluxTauMin * std::ldexp(1.0, kSlabFluxTauNodes - 1);
  for (double edge : {kSlabFluxTauMin, tau_max}) {
    EXPECT_NEAR(slab_diffuse_transmittance(edge * (1.0 - 1e-9)), slab_diffuse_transmittance(edge * (1.0 + 1e-9)), 1e-6);
    EXPECT_NEAR(slab_beam_transmittance(edge * (1.0 - 1e-9), 0.4), slab_beam_transmittance(edge * (1.0 + 1e-9), 0.4), 1e-6);
  }
  for (double tau : {1.0, 16.0, 128.0}) {
    double mean = 0.0;  // midpoint rule in mu over [0.05, 1] plus the first node's value below 0.05
    const int n = 400;
    for (int k = 0; k < n; ++k) {
      const double mu = kSlabFluxMuMin + (k + 0.5) * (1.0 - kSlabFluxMuMin) / n;
      mean += 2.0 * slab_beam_transmittance(tau, mu) * mu * (1.0 - kSlabFluxMuMin) / n;
    }
    mean += slab_beam_transmittance(tau, kSlabFluxMuMin) * kSlabFluxMuMin * kSlabFluxMuMin;
    EXPECT_NEAR(slab_diffuse_transmittance(tau), mean, 0.02 * mean) << "tau " << tau;
  }
}

}  // namespace
}  // namespace cloudsvc::model
