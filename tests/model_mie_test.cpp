// Lorenz-Mie code (renderer/model/mie.h) against published values (Wiscombe 1980 MIEV0
// test cases, Bohren & Huffman 1983 App. A; values in docs/SOURCES.md) and
// against identities of the theory; then the Jendersie & d'Eon phase fit
// (phase_function.h) against size-averaged Mie for water droplets.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "renderer/model/mie.h"
#include "renderer/model/phase_function.h"

namespace {

using namespace cloudsvc::model;
using cplx = std::complex<double>;
constexpr double kPi = std::numbers::pi;

double cos_deg(double deg) { return std::cos(deg * kPi / 180.0); }

// |value - printed| within half a unit of the printed value's last digit (plus 1e-9
// relative for our own rounding): "agrees to the printed digits".
void expect_printed(double value, double printed, double last_digit_unit, const char* what) {
  EXPECT_NEAR(value, printed, 0.5 * last_digit_unit + 1e-9 * std::abs(printed)) << what;
}

// 2 pi int_0^pi f(cos theta) sin theta dtheta by 8-point Gauss-Legendre on `panels`
// equal panels in theta. The x = 100 forward lobe is ~1/x = 0.01 rad wide; 3000 panels
// (1e-3 rad each) resolve it to ~1e-12. Nodes are handed over all at once so the Mie
// phase can be evaluated in one call.
double integrate_sphere(const std::function<std::vector<double>(const std::vector<double>&)>& f,
                        int panels) {
  // 8-point Gauss-Legendre on [-1, 1] (Abramowitz & Stegun Table 25.4).
  static constexpr std::array<double, 4> gx = {0.1834346424956498, 0.5255324099163290,
                                               0.7966664774136267, 0.9602898564975363};
  static constexpr std::array<double, 4> gw = {0.3626837833783620, 0.3137066458778873,
                                               0.2223810344533745, 0.1012285362903763};
  std::vector<double> mu, w;
  const double h = kPi / panels;
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * h;
    for (int k = 0; k < 4; ++k) {
      for (double sgn : {-1.0, 1.0}) {
        const double t = mid + sgn * 0.5 * h * gx[k];
        mu.push_back(std::cos(t));
        w.push_back(gw[k] * 0.5 * h * std::sin(t));
      }
    }
  }
  const std::vector<double> v = f(mu);
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) sum += w[i] * v[i];
  return 2.0 * kPi * sum;
}

// ---------------------------------------------------------------------------------
// Numerics of the series.

TEST(Mie, TermCountIsWiscombes) {
  EXPECT_EQ(mie_n_stop(100.0), 121);      // 100 + 4 * 4.64 + 2 = 120.6
  EXPECT_EQ(mie_n_stop(10000.0), 10088);  // 10000 + 86.2 + 2
  EXPECT_EQ(mie_coefficients(kWiscombeWaterIndex, 100.0).a.size(), 121u);
}

// The continued-fraction start (Lentz) against a plain downward recurrence begun with
// D_N = 0 so far above |z| that the start error has died out (it shrinks by a factor
// (z / 2n)^2 per step for n >> |z|), and against closed forms for n = 0, 1.
TEST(Mie, LogDerivativeMatchesDeepRecurrenceAndClosedForm) {
  for (const cplx z : {cplx(1.33, 1e-5) * 1.0, cplx(1.33, 1e-5) * 100.0,
                       cplx(1.55, 0.0) * 5.2, cplx(1.33, 1e-8) * 10000.0,
                       cplx(1.5, 0.1) * 30.0}) {
    const int n_max = mie_n_stop(std::abs(z)) + 10;
    const std::vector<cplx> d = mie_log_derivatives(z, n_max);
    ASSERT_EQ(d.size(), static_cast<std::size_t>(n_max) + 1);
    const int deep = static_cast<int>(3.0 * std::abs(z)) + 400;
    cplx r = 0.0;
    std::vector<cplx> ref(static_cast<std::size_t>(n_max) + 1);
    for (int n = deep; n >= 1; --n) {
      r = static_cast<double>(n) / z - 1.0 / (r + static_cast<double>(n) / z);
      if (n - 1 <= n_max) ref[static_cast<std::size_t>(n - 1)] = r;
    }
    for (int n : {0, 1, n_max / 2, n_max - 1, n_max}) {
      const auto i = static_cast<std::size_t>(n);
      EXPECT_LT(std::abs(d[i] - ref[i]), 1e-10 * std::abs(ref[i]))
          << "z = " << z << " n = " << n;
      EXPECT_LT(std::abs(mie_log_derivative_cf(z, n) - ref[i]), 1e-10 * std::abs(ref[i]))
          << "continued fraction, z = " << z << " n = " << n;
    }
    // D_0 = cot z, D_1 = -1/z + 1/(1/z - cot z)  (psi_1 = sin z / z - cos z).
    const cplx cot = std::cos(z) / std::sin(z);
    EXPECT_LT(std::abs(d[0] - cot), 1e-10 * std::abs(cot)) << z;
    const cplx d1 = -1.0 / z + 1.0 / (1.0 / z - cot);
    EXPECT_LT(std::abs(d[1] - d1), 1e-10 * std::abs(d1)) << z;
  }
}

// ---------------------------------------------------------------------------------
// Published values.

// Wiscombe 1980 / MIEV0 test cases, m = 1.33 - 1e-5 i, to the printed digits.
TEST(Mie, WiscombeWaterCases) {
  struct Case { double x, q_ext, q_sca, g; };
  for (const Case& c : {Case{1.0, 0.09395198, 0.0939233, 0.184517},
                        Case{100.0, 2.101321, 2.096594, 0.868959},
                        Case{10000.0, 2.004089, 1.723857, 0.907840}}) {
    const MieEfficiencies e = mie_efficiencies(mie_coefficients({1.33, -1e-5}, c.x));
    SCOPED_TRACE("x = " + std::to_string(c.x));
    expect_printed(e.q_ext, c.q_ext, c.x == 1.0 ? 1e-8 : 1e-6, "Q_ext");
    expect_printed(e.q_sca, c.q_sca, c.x == 1.0 ? 1e-7 : 1e-6, "Q_sca");
    expect_printed(e.g, c.g, 1e-6, "g");
    EXPECT_GT(e.q_abs(), 0.0);
  }
}

// Both sign conventions of Im m describe the same droplet.
TEST(Mie, ImaginaryPartSignConvention) {
  const MieEfficiencies a = mie_efficiencies(mie_coefficients({1.33, -1e-5}, 100.0));
  const MieEfficiencies b = mie_efficiencies(mie_coefficients({1.33, 1e-5}, 100.0));
  EXPECT_EQ(a.q_ext, b.q_ext);
  EXPECT_EQ(a.q_back, b.q_back);
}

// Bohren & Huffman App. A (BHMIE example): m = 1.55, lambda = 0.6328 um, r = 0.525 um.
TEST(Mie, BohrenHuffmanExample) {
  const double x = 2.0 * kPi * 0.525 / 0.6328;
  const MieEfficiencies e = mie_efficiencies(mie_coefficients({1.55, 0.0}, x));
  expect_printed(e.q_ext, 3.10543, 1e-5, "Q_ext");
  expect_printed(e.q_sca, 3.10543, 1e-5, "Q_sca");
  expect_printed(e.q_back, 2.92534, 1e-5, "Q_back");
  // No absorption: extinction is all scattering (optical theorem vs. |a|^2 + |b|^2).
  EXPECT_NEAR(e.q_ext, e.q_sca, 1e-12);
}

// Normalised phase function at x = 100, m = 1.33 - 1e-5 i (Wiscombe 1980; docs/SOURCES.md).
TEST(Mie, PhaseValuesAtX100) {
  const std::array<double, 7> deg = {0, 30, 60, 90, 120, 150, 180};
  const std::array<double, 7> ref = {419.22,    8.7416e-2, 1.2352e-2, 1.1770e-3,
                                     1.3624e-3, 1.0555e-2, 8.1465e-2};
  std::vector<double> mu;
  for (double d : deg) mu.push_back(cos_deg(d));
  const MieSingle s = mie_single(kWiscombeWaterIndex, 100.0, mu);
  for (std::size_t i = 0; i < deg.size(); ++i)
    EXPECT_NEAR(s.phase[i] / ref[i], 1.0, 1e-4) << deg[i] << " deg: " << s.phase[i];
}

// ---------------------------------------------------------------------------------
// Identities.

// int p dOmega = 1 and int p cos(theta) dOmega = g: the angular series (S1, S2 from
// pi_n, tau_n) against the efficiency series (Q_sca, g), which share only a_n, b_n.
TEST(Mie, PhaseIntegratesToOneAndToG) {
  for (const double x : {1.0, 100.0}) {
    const MieCoefficients c = mie_coefficients(kWiscombeWaterIndex, x);
    const MieEfficiencies e = mie_efficiencies(c);
    const double norm = integrate_sphere(
        [&](const std::vector<double>& mu) { return mie_phase(c, e.q_sca, mu); }, 3000);
    EXPECT_NEAR(norm, 1.0, 1e-6) << "x = " << x;
    const double mean_cos = integrate_sphere(
        [&](const std::vector<double>& mu) {
          std::vector<double> p = mie_phase(c, e.q_sca, mu);
          for (std::size_t i = 0; i < p.size(); ++i) p[i] *= mu[i];
          return p;
        },
        3000);
    EXPECT_NEAR(mean_cos, e.g, 1e-6) << "x = " << x;
  }
}

// mie_phase evaluates an angle and its mirror image (180 deg - theta) from one recurrence:
// against mie_amplitudes one angle at a time, on a list in no order with mirror pairs,
// unpaired angles, a repeated angle, 0, 90 and 180 deg.
TEST(Mie, MirroredAnglesMatchTheSeriesOneAngleAtATime) {
  const MieCoefficients c = mie_coefficients({1.333, 1e-8}, 140.0);
  const MieEfficiencies e = mie_efficiencies(c);
  std::vector<double> deg = {179.9, 0.0, 0.02, 179.98, 90.0, 37.3, 142.7, 142.7, 5.0, 12.345, 180.0, 60.0};
  std::vector<double> mu;
  for (double d : deg) mu.push_back(std::cos(d * kPi / 180.0));
  const std::vector<double> p = mie_phase(c, e.q_sca, mu);
  ASSERT_EQ(p.size(), mu.size());
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const MieAmplitudes s = mie_amplitudes(c, mu[i]);
    const double one = (std::norm(s.s1) + std::norm(s.s2)) / (2.0 * kPi * c.x * c.x * e.q_sca);
    EXPECT_NEAR(p[i] / one, 1.0, 1e-9) << deg[i] << " deg";
  }
}

// Forward amplitude (optical theorem, B&H 4.76): Q_ext = (4 / x^2) Re S(0), and
// S1 = S2 at 0 and 180 degrees up to sign (S1(180) = -S2(180)).
TEST(Mie, OpticalTheoremAndSymmetry) {
  const MieCoefficients c = mie_coefficients({1.33, 1e-3}, 37.0);
  const MieEfficiencies e = mie_efficiencies(c);
  const MieAmplitudes f = mie_amplitudes(c, 1.0);
  EXPECT_NEAR(4.0 / (c.x * c.x) * f.s1.real(), e.q_ext, 1e-12);
  EXPECT_LT(std::abs(f.s1 - f.s2), 1e-9 * std::abs(f.s1));
  const MieAmplitudes b = mie_amplitudes(c, -1.0);
  EXPECT_LT(std::abs(b.s1 + b.s2), 1e-9 * std::abs(b.s1));
  // Q_back = 4 pi p(180) Q_sca: B&H 4.82 against the angular series.
  const double p180 = mie_phase(c, e.q_sca, {-1.0})[0];
  EXPECT_NEAR(4.0 * kPi * p180 * e.q_sca / e.q_back, 1.0, 1e-10);
}

// Small spheres: Rayleigh limit, Q_sca = (8/3) x^4 |K|^2 and Q_abs = 4 x Im K with
// K = (m^2 - 1) / (m^2 + 2), B&H 5.8; corrections are O(x^2).
TEST(Mie, RayleighLimit) {
  const cplx m(1.5, 0.1);
  const double x = 0.01;
  const cplx k = (m * m - 1.0) / (m * m + 2.0);
  const MieEfficiencies e = mie_efficiencies(mie_coefficients(m, x));
  EXPECT_NEAR(e.q_sca / (8.0 / 3.0 * std::pow(x, 4) * std::norm(k)), 1.0, 1e-3);
  EXPECT_NEAR(e.q_abs() / (4.0 * x * k.imag()), 1.0, 1e-3);
  EXPECT_NEAR(e.g, 0.0, 1e-3);
}

// ---------------------------------------------------------------------------------
// Size-distribution average.

TEST(MieAverage, ZeroSpreadIsOneSphere) {
  DropletSpectrum s;
  s.mean_diameter_um = 10.0;
  s.relative_spread = 0.0;
  const std::vector<double> mu = {1.0, cos_deg(90), -1.0};
  const MieAverage a = mie_size_average(s, mu);
  const MieSingle one = mie_single(s.m, kPi * 10.0 / s.wavelength_um, mu);
  EXPECT_EQ(a.sizes, 1);
  EXPECT_DOUBLE_EQ(a.q_ext, one.eff.q_ext);
  EXPECT_DOUBLE_EQ(a.g, one.eff.g);
  for (std::size_t i = 0; i < mu.size(); ++i) EXPECT_DOUBLE_EQ(a.phase[i], one.phase[i]);
}

// The C_sca-weighted average phase stays normalised and its mean cosine is the averaged
// g; the effective diameter <d^3>/<d^2> of the gamma distribution (shape k = 1/s^2 = 100,
// scale d/k: <d^n> ~ Gamma(k+n)/Gamma(k)) is d (k+2)/k = 1.02 d.
TEST(MieAverage, NormalisedAndConsistent) {
  DropletSpectrum s;
  s.mean_diameter_um = 10.0;
  s.sizes = 41;  // coarse: the identities hold for any quadrature
  const auto avg = [&](const std::vector<double>& mu) { return mie_size_average(s, mu).phase; };
  EXPECT_NEAR(integrate_sphere(avg, 2000), 1.0, 1e-6);
  const MieAverage a = mie_size_average(s, {1.0});
  const double g_int = integrate_sphere(
      [&](const std::vector<double>& mu) {
        std::vector<double> p = avg(mu);
        for (std::size_t i = 0; i < p.size(); ++i) p[i] *= mu[i];
        return p;
      },
      2000);
  EXPECT_NEAR(g_int, a.g, 1e-6);
  const double k = 100.0;
  EXPECT_NEAR(a.effective_diameter_um / (10.0 * (k + 2.0) / k), 1.0, 1e-3);
  // Q_ext of cloud droplets ~ 2 (droplet_optics.h uses 2; here 2.13 at 10 um).
  EXPECT_GT(a.q_ext, 2.0);
  EXPECT_LT(a.q_ext, 2.2);
}

// ---------------------------------------------------------------------------------
// Jendersie & d'Eon fit vs Mie: water m = 1.333 - 1e-8 i, lambda = 0.55 um, gamma
// distribution of diameters with 10 % relative spread, default quadrature (spacing 0.01
// in x: the 180 deg ratio is converged to ~0.3 %; a lognormal of the same mean and
// spread changes the ratios below by < 1 %, the 180 deg one by < 5 %).
//
// Measured p_fit / p_Mie (this code):
//   deg     5     10    20    30    45    90    120   125   130   138   142   145   180
//   d=10  0.764 1.008 0.995 1.017 1.018 0.585 1.537 1.726 1.661 0.616 0.434 0.457 0.238
//   d=20  1.083 1.045 1.042 1.012 0.961 0.579 1.359 1.341 1.913 0.473 0.294 0.558 0.207
//   g_Mie 0.8517 (d=10), 0.8657 (d=20); g_fit 0.8642, 0.8793.
// Against the bands of docs/SOURCES.md ("Jendersie & d'Eon 2023 phase function"):
//  * 5-45 deg "0.97-1.02": not at 5 deg (diffraction ring at 0.55 um, see the next test)
//    and not for d = 20 at 10-20 deg, where the fit is 4-5 % high (max 1.050 at 13-14
//    deg; the same for lognormal and for spreads 10-30 %). Asserted: 0.95-1.05 at
//    10/20/30/45 deg.
//  * cloudbow 138-145 "0.3-0.6": d = 10 reaches 0.616 at 138 deg and d = 20 dips to
//    0.294 at 141-142 deg. Asserted: 0.25-0.65.
//  * 120-130 "1.3-2.0" holds at 120/125/130 (d = 20 dips to 1.26 at 122-123 deg).
//  * 90 deg "~0.58" and 180 deg "0.2-0.26" hold.
struct FitVsMie {
  std::vector<double> deg;
  std::vector<double> ratio;
  double g_mie = 0.0;
  double g_fit = 0.0;
  double q_ext = 0.0;
  double at(double angle) const {
    for (std::size_t i = 0; i < deg.size(); ++i)
      if (deg[i] == angle) return ratio[i];
    ADD_FAILURE() << "angle not tabulated: " << angle;
    return 0.0;
  }
};

const FitVsMie& fit_vs_mie(double d) {
  static std::map<double, FitVsMie> cache;  // map: references stay valid
  if (const auto it = cache.find(d); it != cache.end()) return it->second;
  FitVsMie r;
  r.deg = {5, 10, 20, 30, 45, 90, 120, 125, 130, 138, 142, 145, 180};
  std::vector<double> mu;
  for (double a : r.deg) mu.push_back(cos_deg(a));
  DropletSpectrum s;
  s.mean_diameter_um = d;  // gamma, 10 %, 0.55 um, m = 1.333 - 1e-8 i (defaults)
  const MieAverage avg = mie_size_average(s, mu);
  const JdDParams fit = jdd_params(d);
  for (std::size_t i = 0; i < mu.size(); ++i) {
    r.ratio.push_back(jdd_phase(mu[i], fit) / avg.phase[i]);
    std::printf("d = %g um, %5.0f deg: p_fit/p_Mie = %.3f\n", d, r.deg[i], r.ratio.back());
  }
  r.g_mie = avg.g;
  r.g_fit = jdd_mean_cosine(fit);
  r.q_ext = avg.q_ext;
  return cache.emplace(d, r).first->second;
}

class JdDVsMie : public ::testing::TestWithParam<double> {};

TEST_P(JdDVsMie, ForwardLobe10To45Deg) {
  const FitVsMie& r = fit_vs_mie(GetParam());
  for (double a : {10.0, 20.0, 30.0, 45.0}) {
    EXPECT_GT(r.at(a), 0.95) << a << " deg";
    EXPECT_LT(r.at(a), 1.05) << a << " deg";
  }
}

TEST_P(JdDVsMie, SideScatter90Deg) {
  const double v = fit_vs_mie(GetParam()).at(90);
  EXPECT_GT(v, 0.54);
  EXPECT_LT(v, 0.62);
}

TEST_P(JdDVsMie, Between120And130Deg) {
  const FitVsMie& r = fit_vs_mie(GetParam());
  for (double a : {120.0, 125.0, 130.0}) {
    EXPECT_GT(r.at(a), 1.3) << a << " deg";
    EXPECT_LT(r.at(a), 2.0) << a << " deg";
  }
}

TEST_P(JdDVsMie, CloudbowIsUnderestimated) {
  const FitVsMie& r = fit_vs_mie(GetParam());
  for (double a : {138.0, 142.0, 145.0}) {
    EXPECT_GT(r.at(a), 0.25) << a << " deg";
    EXPECT_LT(r.at(a), 0.65) << a << " deg";
  }
}

TEST_P(JdDVsMie, GloryIsUnderestimated180Deg) {
  const double v = fit_vs_mie(GetParam()).at(180);
  EXPECT_GT(v, 0.19);
  EXPECT_LT(v, 0.27);
}

// The fit's mean cosine is 0.012-0.014 above Mie's (a brighter forward peak), and the
// averaged Q_ext is near the 2 used for extinction (2.13 at 10 um, 2.08 at 20 um).
TEST_P(JdDVsMie, AsymmetryAndExtinction) {
  const FitVsMie& r = fit_vs_mie(GetParam());
  EXPECT_GT(r.g_fit - r.g_mie, 0.005);
  EXPECT_LT(r.g_fit - r.g_mie, 0.02);
  EXPECT_GT(r.q_ext, 2.0);
  EXPECT_LT(r.q_ext, 2.2);
}

INSTANTIATE_TEST_SUITE_P(Diameters, JdDVsMie, ::testing::Values(10.0, 20.0),
                         [](const auto& info) {
                           std::string name = std::to_string(static_cast<int>(info.param));
                           name += "um";  // ("d" + to_string trips GCC 12's -Wrestrict)
                           return name;
                         });

// At 5 deg and 0.55 um, the d = 10 um distribution is still inside its first diffraction
// ring (x sin(theta) ~ 5 for x = 57, ring maximum at 5.1), which the smooth HG lobe
// cannot follow: the fit is 24 % low there. Averaged over the visible band (flat
// spectrum, 0.40-0.70 um, weights C_sca) the rings wash out and the ratio comes back to
// ~1.03, inside the 5-45 deg band; the 0.55-um-only d = 20 value 1.08 comes to ~0.98.
TEST(JdDVsMieFiveDeg, DiffractionRingAndVisibleBandAverage) {
  const std::vector<double> mu = {cos_deg(5.0)};
  EXPECT_GT(fit_vs_mie(10.0).at(5), 0.65);
  EXPECT_LT(fit_vs_mie(10.0).at(5), 0.85);
  for (double d : {10.0, 20.0}) {
    double sum_p = 0.0, sum_w = 0.0;
    for (int i = 0; i <= 30; ++i) {
      DropletSpectrum s;
      s.mean_diameter_um = d;
      s.wavelength_um = 0.40 + 0.01 * i;
      s.sizes = 200;  // the forward lobe needs no resonance resolution
      const MieAverage a = mie_size_average(s, mu);
      sum_p += a.q_sca * a.phase[0];  // <C_sca> / <pi d^2/4> is the same d for all lambda
      sum_w += a.q_sca;
    }
    const double ratio = jdd_phase(mu[0], jdd_params(d)) / (sum_p / sum_w);
    std::printf("d = %g um, 5 deg, 0.40-0.70 um average: p_fit/p_Mie = %.3f\n", d, ratio);
    EXPECT_GT(ratio, 0.95) << "d = " << d;
    EXPECT_LT(ratio, 1.05) << "d = " << d;
  }
}

}  // namespace
