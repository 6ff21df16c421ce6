// The slab transmittance table (see slab_flux_table.h).
#include "renderer/model/slab_flux_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "renderer/model/ms_source_table.h"
#include "renderer/model/phase_function.h"
#include "renderer/model/slab_monte_carlo.h"

namespace cloudsvc::model {

namespace {

constexpr double kTauMax = kSlabFluxTauMin * (1 << (kSlabFluxTauNodes - 1));

// f(tau) from its values at the tau nodes, value(i) (see slab_flux_table.h).
template <typename NodeValue>
double interpolate_in_tau(double tau, const NodeValue& value) {
  if (!(tau > 0.0)) return 1.0;
  const double x = std::log2(tau / kSlabFluxTauMin);
  if (x <= 0.0) return 1.0 - (1.0 - value(0)) * tau / kSlabFluxTauMin;
  if (x >= kSlabFluxTauNodes - 1) {
    const double b = slab_flux_table().diffusion_offset;
    return value(kSlabFluxTauNodes - 1) * (kTauMax + b) / (tau + b);
  }
  const int i = static_cast<int>(x);
  const double f = x - i;
  return value(i) + (value(i + 1) - value(i)) * f;
}

// 8-point Gauss-Legendre nodes and weights on [0, 1] (Abramowitz & Stegun 1964, 25.4.30).
constexpr double kGaussX[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355, 0.4082826787521751,
                               0.5917173212478249, 0.7627662049581645, 0.8983332387068134, 0.9801449282487681};
constexpr double kGaussW[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436, 0.1813418916891810,
                               0.1813418916891810, 0.1568533229389436, 0.1111905172266872, 0.0506142681451881};

}  // namespace

const SlabFluxTable& slab_flux_table() {
  static const SlabFluxTable table{
#include "renderer/model/data/slab_flux_table.inc"
  };
  return table;
}

double slab_beam_transmittance(double tau, double mu0) {
  const SlabFluxTable& t = slab_flux_table();
  const double m = std::clamp((mu0 - kSlabFluxMuMin) / kSlabFluxMuStep, 0.0, double(kSlabFluxMuNodes - 1));
  const int j = std::min(static_cast<int>(m), kSlabFluxMuNodes - 2);
  const double f = m - j;
  return interpolate_in_tau(tau, [&](int i) {
    const float* row = &t.beam[static_cast<std::size_t>(i * kSlabFluxMuNodes)];
    return row[j] + (row[j + 1] - row[j]) * f;
  });
}

double slab_diffuse_transmittance(double tau) {
  const SlabFluxTable& t = slab_flux_table();
  return interpolate_in_tau(tau, [&](int i) { return double(t.diffuse[static_cast<std::size_t>(i)]); });
}

SlabFluxTableBuild build_slab_flux_table(std::uint64_t photons, std::uint64_t seed, int threads) {
  const auto t0 = std::chrono::steady_clock::now();
  SlabFluxTableBuild out;
  std::uint64_t node = 0;
  auto transmitted = [&](double tau, double mu0) {
    SlabMcOptions o;
    o.photons = static_cast<std::uint64_t>(static_cast<double>(photons) * (1.0 + tau / 8.0));
    o.seed = seed * 1000003ULL + node++;
    o.threads = threads;
    o.ddis_probability = 0.0;  // fluxes only: no views
    const SlabMcResult r =
        run_slab_monte_carlo(slab_from_optical_depth(tau, std::acos(mu0) * 180.0 / std::numbers::pi, kMsTableDropletUm), o);
    out.max_relative_se = std::max(out.max_relative_se, r.transmitted.std_error / r.transmitted.mean);
    return r.transmitted.mean;
  };
  out.table.diffusion_offset = static_cast<float>(2.0 * 0.7104 / (1.0 - jdd_mean_cosine(jdd_params(kMsTableDropletUm))));
  for (int i = 0; i < kSlabFluxTauNodes; ++i) {
    const double tau = kSlabFluxTauMin * std::ldexp(1.0, i);
    for (int j = 0; j < kSlabFluxMuNodes; ++j)
      out.table.beam[static_cast<std::size_t>(i * kSlabFluxMuNodes + j)] =
          static_cast<float>(transmitted(tau, slab_flux_mu_node(j)));
    double diffuse = 0.0;
    for (int k = 0; k < 8; ++k) diffuse += 2.0 * kGaussW[k] * kGaussX[k] * transmitted(tau, kGaussX[k]);
    out.table.diffuse[static_cast<std::size_t>(i)] = static_cast<float>(diffuse);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cloudsvc::model
