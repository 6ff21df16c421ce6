// Transmittance of a conservative cloud slab, tabulated from the slab Monte Carlo
// (slab_monte_carlo.h): what the light model uses for the light that crosses a whole layer
// (the ground under a deck, the deck's reflectance from below) and for the diffuse fluxes
// at a depth inside one (cloud_lighting.h, shaders/slab_transmittance.glsl).
//
// Replaces the delta-Eddington two-stream closed forms (Joseph, Wiscombe & Weinman 1976),
// which against the Monte Carlo put the sun's transmitted flux 5-11 % low under thick
// slabs and a high sun and 10-37 % high under a low sun (mu0 < 0.2), and the diffuse
// transmittance 5-8 % low at optical depths 32-128 (bench/slab_flux_table.cpp prints both).
//
// Slab: homogeneous, conservative, the Jendersie-d'Eon phase function of the
// model::kMsTableDropletUm droplets, black ground, no atmosphere. Fluxes are fractions of
// the incident flux (per unit horizontal flux), direct and diffuse together.
#pragma once

#include <array>
#include <cstdint>

namespace cloudsvc::model {

// Grid: optical depths tau_i = kSlabFluxTauMin 2^i (i < kSlabFluxTauNodes, 0.25 .. 128),
// sun zenith cosines mu_j = kSlabFluxMuMin + j kSlabFluxMuStep (j < kSlabFluxMuNodes,
// 0.05 .. 1). Interpolation: linear in log2 tau and in mu (clamped to the nodes). Thinner
// slabs: 1 - (1 - T(tau_min)) tau / tau_min (T -> 1 linearly); thicker ones follow the
// diffusion limit T(tau) = T(tau_max) (tau_max + b) / (tau + b), b = 2 z_e the two
// extrapolation depths of the boundaries, z_e = 0.7104 / (1 - g) (the Milne problem's
// extrapolation length in transport mean free paths, e.g. Case & Zweifel 1967; g the
// phase function's mean cosine).
inline constexpr int kSlabFluxTauNodes = 10;
inline constexpr double kSlabFluxTauMin = 0.25;
inline constexpr int kSlabFluxMuNodes = 11;
inline constexpr double kSlabFluxMuMin = 0.05;
inline constexpr double kSlabFluxMuStep = 0.095;
// The sun zenith cosine of node j.
inline constexpr double slab_flux_mu_node(int j) { return kSlabFluxMuMin + j * kSlabFluxMuStep; }

struct SlabFluxTable {
  // beam[i * kSlabFluxMuNodes + j]: total transmittance T(tau_i, mu_j) of a collimated beam
  std::array<float, kSlabFluxTauNodes * kSlabFluxMuNodes> beam{};
  // diffuse[i]: transmittance of diffuse (Lambertian) incident light, 2 int_0^1 T(tau_i, mu) mu dmu
  std::array<float, kSlabFluxTauNodes> diffuse{};
  float diffusion_offset = 0.0f;  // b above (optical depth)
};

// The table the renderer uses (renderer/model/data/slab_flux_table.inc, written by
// build/bin/slab_flux_table).
const SlabFluxTable& slab_flux_table();

// Total transmittance of a collimated beam at zenith cosine mu0 (> 0) through a slab of
// optical depth tau >= 0 (1 at tau = 0).
double slab_beam_transmittance(double tau, double mu0);
// Transmittance of diffuse light (1 at tau = 0). Conservative slab: its reflectance for
// diffuse light is 1 minus this.
double slab_diffuse_transmittance(double tau);

// Monte Carlo of every node (build/bin/slab_flux_table): photons (1 + tau / 8) per beam
// node, as many for each of the 8 Gauss-Legendre nodes in mu the diffuse column
// integrates (thick slabs transmit few photons); the largest standard error relative to
// the value over the table in max_relative_se.
struct SlabFluxTableBuild {
  SlabFluxTable table;
  double max_relative_se = 0.0;
  double seconds = 0.0;
};
SlabFluxTableBuild build_slab_flux_table(std::uint64_t photons, std::uint64_t seed, int threads);

}  // namespace cloudsvc::model
