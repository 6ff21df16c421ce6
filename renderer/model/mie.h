// Lorenz-Mie scattering by a homogeneous sphere, and its average over a droplet size
// distribution. Independent physical check of the Jendersie & d'Eon phase fit
// (phase_function.h) and of Q_ext ~= 2 (droplet_optics.h); not used while rendering.
//
// Sources: Bohren & Huffman 1983, "Absorption and Scattering of Light by Small
// Particles", ch. 4 (series, recurrences, efficiencies; eqs. 4.50-4.77) and App. A;
// Wiscombe 1980, "Improved Mie scattering algorithms", Appl. Opt. 19, 1505 (number of
// terms, downward recurrence for the logarithmic derivative); Lentz 1976, Appl. Opt. 15,
// 668 (continued fraction for the start value of that recurrence).
//
// Conventions (Bohren & Huffman, time factor exp(-i w t)): refractive index relative to
// the medium m = n + i k with k >= 0 for absorption. Wiscombe's m = n - i k (time factor
// exp(+i w t)) describes the same material: every function here uses |Im m|, so
// {1.33, -1e-5} and {1.33, 1e-5} are the same droplet. Efficiencies, g and |S|^2 do not
// depend on the convention; the phase of S1, S2 does (B&H's is returned).
// Size parameter x = 2 pi r / lambda = pi d / lambda (r radius, d diameter, lambda the
// wavelength in the medium; air ~ vacuum here). Double precision; tested up to x = 1e4
// (Wiscombe's x = 10000 case to 1e-7).
#pragma once

#include <complex>
#include <vector>

namespace cloudsvc::model {

// Liquid water at 0.55 um (Hale & Querry 1973: n = 1.333, k ~ 2e-9; k is rounded up to
// 1e-8 as in the brief: with k = 2e-9 instead, the 10 %-spread phase changes by < 5e-5
// at d <= 20 um and < 2e-4 at 50 um, g by < 1e-6). Wiscombe's 1.33 moves the cloudbow:
// p_fit/p_Mie at 138-145 deg shifts by up to ~0.1 (d = 10-50 um).
inline constexpr std::complex<double> kWaterIndex550nm{1.333, 1.0e-8};
// Wiscombe's MIEV0 test cases use m = 1.33 - 1e-5 i.
inline constexpr std::complex<double> kWiscombeWaterIndex{1.33, 1.0e-5};
inline constexpr double kVisibleWavelengthUm = 0.55;

// Number of series terms (Wiscombe 1980 / Bohren & Huffman): n_stop = x + 4 x^(1/3) + 2,
// rounded to the nearest integer, at least 1.
int mie_n_stop(double x);

// Logarithmic derivative D_n(z) = psi_n'(z) / psi_n(z) of the Riccati-Bessel function
// psi_n(z) = z j_n(z), for one n >= 0, by Lentz's continued fraction for
// J_{n-1/2}(z) / J_{n+1/2}(z) (D_n = -n/z + that ratio); converged to 1e-15 per step,
// agrees with a deep downward recurrence to < 1e-10 in the tests. Used as the exact
// start of the downward recurrence: a start D_N = 0 at N = |mx| + 40 is still 2 % off
// at n_stop for x = 1e4 (the start error hardly decays while n ~ |mx|).
std::complex<double> mie_log_derivative_cf(std::complex<double> z, int n);

// D_0(z) .. D_{n_max}(z) (size n_max + 1) by the downward recurrence
//   D_{n-1} = n/z - 1 / (D_n + n/z),
// stable in this direction for all n (Wiscombe 1980). Started at
// N = max(n_max, |z|) + 40 with D_N from the continued fraction above, so the start is
// exact rather than "D_N = 0 far enough up" (B&H's BHMIE start max(n_stop, |mx|) + 15
// leaves a 1e-5 error at x = 100; docs/SOURCES.md, "Lorenz-Mie test cases").
std::vector<std::complex<double>> mie_log_derivatives(std::complex<double> z, int n_max);

// Series coefficients a_n, b_n for n = 1 .. n_stop (stored at index n - 1).
struct MieCoefficients {
  double x = 0.0;                         // size parameter
  std::complex<double> m{1.0, 0.0};       // refractive index, Im >= 0 (B&H convention)
  std::vector<std::complex<double>> a;    // electric multipole coefficients a_n
  std::vector<std::complex<double>> b;    // magnetic multipole coefficients b_n
};

// a_n, b_n of B&H eq. 4.88 (with D_n(mx) in place of psi_n'(mx)/psi_n(mx)); psi_n(x)
// and chi_n(x) by upward recurrence, which is accurate enough up to n_stop (Wiscombe).
// x > 0, Re m > 0.
MieCoefficients mie_coefficients(std::complex<double> m, double x);

// Efficiencies (cross section / pi r^2) and asymmetry parameter.
struct MieEfficiencies {
  double q_ext = 0.0;   // extinction, B&H 4.62
  double q_sca = 0.0;   // scattering, B&H 4.61
  double q_back = 0.0;  // backscatter, B&H 4.82: 4 pi (dC_sca/dOmega)(180 deg) / pi r^2
  double g = 0.0;       // <cos theta>, B&H 4.74
  double q_abs() const { return q_ext - q_sca; }
};
MieEfficiencies mie_efficiencies(const MieCoefficients& c);

// Scattering amplitudes S1 (perpendicular), S2 (parallel) at cos(theta), B&H 4.74
// with the angular functions pi_n, tau_n by upward recurrence (B&H 4.47).
struct MieAmplitudes {
  std::complex<double> s1;
  std::complex<double> s2;
};
MieAmplitudes mie_amplitudes(const MieCoefficients& c, double cos_theta);

// Unpolarised phase function normalised over the sphere (sr^-1, int p dOmega = 1):
//   p(theta) = (|S1|^2 + |S2|^2) / (2 pi x^2 Q_sca).
// One value per entry of cos_theta. q_sca must be mie_efficiencies(c).q_sca.
std::vector<double> mie_phase(const MieCoefficients& c, double q_sca,
                              const std::vector<double>& cos_theta);

// Everything for one sphere at once: the efficiencies and p at the given angles.
struct MieSingle {
  MieEfficiencies eff;
  std::vector<double> phase;  // sr^-1, one per cos_theta
};
MieSingle mie_single(std::complex<double> m, double x, const std::vector<double>& cos_theta);

// ---- Size distribution average (polydisperse cloud) -----------------------------

enum class DropletShape {
  kGamma,      // n(d) ~ d^(k-1) exp(-k d / d_mean), k = 1 / spread^2
  kLognormal,  // ln d normal, sigma^2 = ln(1 + spread^2), mean of d = d_mean
};

// Droplet diameter distribution (number density per unit diameter), both shapes with
// mean diameter d_mean and relative standard deviation `spread` (0.10 = 10 %).
struct DropletSpectrum {
  double mean_diameter_um = 10.0;
  double relative_spread = 0.10;
  DropletShape shape = DropletShape::kGamma;
  double wavelength_um = kVisibleWavelengthUm;
  std::complex<double> m = kWaterIndex550nm;
  // Quadrature: uniform in d over +-6 standard deviations (gamma) or +-6 sigma of ln d
  // (lognormal), trapezoid rule (the weights vanish at both ends). 0 = automatic:
  // spacing size_parameter_step in size parameter (at 0.01 the backscatter average over
  // resonances converges to ~0.3 %), at least 64 sizes. Spread 0 = one size.
  int sizes = 0;
  double size_parameter_step = 0.01;
};

// Averages weighted by the number distribution n(d):
//   Q_ext = <C_ext> / <pi d^2 / 4>, Q_sca likewise,
//   g = <C_sca g> / <C_sca>,  p(theta) = <C_sca p(theta)> / <C_sca>  (sr^-1).
struct MieAverage {
  double q_ext = 0.0;
  double q_sca = 0.0;
  double g = 0.0;
  double effective_diameter_um = 0.0;  // <d^3> / <d^2>
  int sizes = 0;                       // number of diameters evaluated
  std::vector<double> phase;           // sr^-1, one per cos_theta
};
// threads: common/parallel_for.h (0 = every hardware thread). The sizes are summed in
// fixed chunks in chunk order, so the result does not depend on the thread count.
MieAverage mie_size_average(const DropletSpectrum& s, const std::vector<double>& cos_theta, int threads = 1);

}  // namespace cloudsvc::model
