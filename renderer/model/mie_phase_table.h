// The Lorenz-Mie phase function of a cloud layer's droplets, tabulated at the three
// rendered wavelengths (rgb = 680 / 550 / 440 nm) for the renderer, the CPU reference and
// the path-traced truth: the glory (coloured rings around the antisolar point) and the
// fogbow (~40 deg from it) at the angles Mie gives for the droplet size, which the
// Jendersie & d'Eon fit (phase_function.h) smooths away (Bouthors et al. 2008 §3.3 render
// both from a tabulated Mie phase function).
//
// Droplets: a gamma distribution of diameters (mie.h, DropletShape::kGamma) with the
// layer's mean diameter and kDropletRelativeSpread; liquid water with the refractive index
// of Hale & Querry 1973 at each wavelength. Averaged with mie_size_average at a size
// parameter step of kPhaseTableSizeStep.
//
// Angles: the table holds p at kPhaseTableSamples scattering angles, 0.02 deg apart from 0
// to 5 deg (the diffraction peak of a 50 um droplet at 440 nm is ~0.3 deg wide) and 0.1 deg
// apart from 5 to 180 deg; a reader interpolates linearly in the angle
// (phase_table_position). Each channel is normalised so that the interpolated p integrates
// to 1 over the sphere.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace cloudsvc::model {

// Which phase function the cloud layers scatter with.
enum class CloudPhaseModel {
  kFit,  // Jendersie & d'Eon 2023 HG + Draine fit (phase_function.h), grey
  kMie,  // this table, per wavelength
};
// Command-line names: "fit", "mie".
const char* cloud_phase_model_name(CloudPhaseModel m);
std::optional<CloudPhaseModel> cloud_phase_model_from_name(std::string_view name);

// Relative standard deviation of the droplet diameters. Wider spectra wash out the glory's
// outer rings and the fogbow's supernumeraries; the first glory ring and the fogbow stay.
inline constexpr double kDropletRelativeSpread = 0.10;
// Size parameter step of the size average (mie.h). Against a step of 0.01 the table differs
// by < 3 % at any angle for 10 % spread (tests/model_mie_phase_table_test.cpp); a step of
// 0.1 leaves 13 % in the backscatter (the glory) at 10 um.
inline constexpr double kPhaseTableSizeStep = 0.05;

// Liquid water's refractive index at 680 / 550 / 440 nm (Hale & Querry 1973, interpolated
// in their table: 1.331, 1.333, 1.3378); the absorption index, ~1e-9 in the visible, is
// rounded up to 1e-8 as for kWaterIndex550nm (mie.h).
inline constexpr double kRenderedWavelengthsUm[3] = {0.68, 0.55, 0.44};
inline constexpr double kWaterRealIndexRgb[3] = {1.331, 1.333, 1.3378};

inline constexpr int kPhaseTableForwardIntervals = 250;   // 0..5 deg at 0.02 deg
inline constexpr int kPhaseTableRearIntervals = 1750;     // 5..180 deg at 0.1 deg
inline constexpr int kPhaseTableSamples = kPhaseTableForwardIntervals + kPhaseTableRearIntervals + 1;
inline constexpr double kPhaseTableForwardEndDeg = 5.0;

// Scattering angle (deg) of table sample i, and the continuous sample position of an angle
// (deg, clamped to [0, 180]): sample i sits at position i.
double phase_table_angle_deg(int i);
double phase_table_position(double theta_deg);

struct PhaseTable {
  double mean_diameter_um = 0.0;
  double effective_diameter_um = 0.0;  // <d^3> / <d^2>
  double relative_spread = 0.0;
  std::vector<glm::dvec3> phase;       // sr^-1 per sample, rgb
  glm::dvec3 g{0.0};                   // asymmetry parameter per channel
  glm::dvec3 normalisation{1.0};       // what the interpolated table integrated to before scaling
  // Per channel, the cumulative solid-angle integral of p up to each sample: 0 at 0 deg,
  // 1 at 180 deg. For sampling directions (sample_cos).
  std::array<std::vector<double>, 3> cdf;

  // p (sr^-1, rgb) at a scattering angle (deg), linear in the angle between samples.
  glm::dvec3 at_angle_deg(double theta_deg) const;
  // p at the cosine of the scattering angle (1 = forward).
  glm::dvec3 at_cos(double cos_theta) const;
  // The cosine of a scattering angle drawn with density at_cos(.)[channel] (exactly: the
  // interval by the CDF, the angle inside it by rejection against p sin(theta)). uniform()
  // returns independent numbers in [0, 1). A spectral path tracer picks the channel in
  // proportion to its path throughput, so the per-channel weights p_c / (throughput-weighted
  // mean of p) keep the throughput's sum (renderer/truth/path_tracer.cpp).
  template <typename Uniform>
  double sample_cos(int channel, Uniform&& uniform) const;
};

template <typename Uniform>
double PhaseTable::sample_cos(int channel, Uniform&& uniform) const {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  const double u = uniform();
  // the interval [i, i + 1] holding u in the CDF
  const std::vector<double>& c = cdf[static_cast<std::size_t>(channel)];
  std::size_t lo = 0, hi = c.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = (lo + hi) / 2;
    (c[mid] <= u ? lo : hi) = mid;
  }
  const int i = static_cast<int>(lo);
  const double a = phase_table_angle_deg(i) * kDeg, b = phase_table_angle_deg(i + 1) * kDeg;
  const double pa = phase[lo][channel], pb = phase[lo + 1][channel];
  // the density inside the interval is (linear p) sin(theta); its bound on the interval:
  const double bound = std::max(pa, pb) * (a < 1.5707963267948966 && b > 1.5707963267948966 ? 1.0 : std::max(std::sin(a), std::sin(b)));
  for (;;) {
    const double f = uniform();
    const double theta = a + (b - a) * f;
    if (uniform() * bound <= (pa + (pb - pa) * f) * std::sin(theta)) return std::cos(theta);
  }
}

// Computes the table (~1-10 s on one core for 5-50 um; threads as common/parallel_for.h).
PhaseTable compute_mie_phase_table(double mean_diameter_um, double relative_spread = kDropletRelativeSpread,
                                   int threads = 0);

// The table for a layer's droplet diameter (um, clamped to [5, 50]) rounded to 0.1 um,
// computed on first use on a thread of its own and kept for the life of the process
// (thread-safe: every caller asking for a diameter under way gets the same future).
using PhaseTableFuture = std::shared_future<std::shared_ptr<const PhaseTable>>;
PhaseTableFuture mie_phase_table_future(double mean_diameter_um);
// The same, waiting for it.
std::shared_ptr<const PhaseTable> mie_phase_table(double mean_diameter_um);

// Angle (rad) between two unit vectors without cancellation at 0 or pi:
// 2 atan2(|a - b|, |a + b|).
double angle_between(const glm::dvec3& a, const glm::dvec3& b);

}  // namespace cloudsvc::model
