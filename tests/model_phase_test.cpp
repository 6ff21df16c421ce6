// Jendersie & d'Eon 2023 HG + Draine cloud phase function and droplet extinction,
// against the values of docs/SOURCES.md and by numerical integration over the sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "renderer/model/droplet_optics.h"
#include "renderer/model/phase_function.h"

namespace {

using namespace cloudsvc::model;

constexpr double kPi = std::numbers::pi;

// ---------------------------------------------------------------------------------
// Integration over the sphere of an azimuthally symmetric f(mu):
//   int f dOmega = 2 pi int_{-1}^{1} f(mu) dmu = 2 pi int f(1 - u) u d(ln u),  u = 1 - mu.
// The forward peak has width (1 - g)^2 / (2g) ~ 2e-6 in u for g = 0.998, so the grid is
// uniform in ln u (from u = 1e-16, below which the integrand is < 1e-12, up to u = 2),
// with 16-point Gauss-Legendre on each of 400 panels.
double integrate_sphere(const std::function<double(double)>& f) {
  // 16-point Gauss-Legendre nodes/weights on [-1, 1] (Abramowitz & Stegun Table 25.4).
  static constexpr std::array<double, 8> x = {
      0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
      0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
  static constexpr std::array<double, 8> w = {
      0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
      0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
  const double a = std::log(1e-16), b = std::log(2.0);
  const int panels = 400;
  const double hp = (b - a) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double mid = a + (p + 0.5) * hp, half = 0.5 * hp;
    for (int k = 0; k < 8; ++k) {
      for (double sgn : {-1.0, 1.0}) {
        const double lnu = mid + sgn * half * x[k];
        const double u = std::exp(lnu);
        sum += w[k] * half * f(1.0 - u) * u;
      }
    }
  }
  return 2.0 * kPi * sum;
}

// The integrator itself, on functions with known integrals (including a sharp HG lobe
// in closed form: int p_HG dOmega = 1, int mu p_HG dOmega = g).
TEST(SphereIntegrator, KnownIntegrals) {
  EXPECT_NEAR(integrate_sphere([](double) { return 1.0; }), 4.0 * kPi, 1e-12);
  EXPECT_NEAR(integrate_sphere([](double mu) { return mu * mu; }), 4.0 * kPi / 3.0, 1e-12);
  // Sharper than any fitted lobe (g_HG <= 0.998). Not much sharper: the phase API
  // takes mu, which resolves 1 - mu only to ~1e-16, i.e. ~1e-8 of a peak of width
  // (1 - g)^2 / 2g = 5e-9 (g = 0.9999) but ~1e-10 of this one.
  const double g = 0.999;
  auto hg = [g](double mu) {
    const double den = (1.0 - g) * (1.0 - g) + 2.0 * g * (1.0 - mu);
    return (1.0 - g) * (1.0 + g) / (4.0 * kPi * den * std::sqrt(den));
  };
  EXPECT_NEAR(integrate_sphere(hg), 1.0, 1e-9);
  EXPECT_NEAR(integrate_sphere([&](double mu) { return mu * hg(mu); }), g, 1e-9);
}

// ---------------------------------------------------------------------------------
// Parameters: docs/SOURCES.md table (computed from the published fits with the
// minus signs of Ford 2024 eqs. 3.14-3.17 and w_D's constant 0.665888).

struct ParamRow {
  double d, g_hg, g_d, alpha, w_d;
};
constexpr ParamRow kParamTable[] = {
    {5.0, 0.970678, 0.508342, 17.068098, 0.447829},
    {10.0, 0.988177, 0.555671, 21.995521, 0.481955},
    {20.0, 0.994610, 0.593791, 27.113694, 0.498159},
    {50.0, 0.997952, 0.625084, 32.315428, 0.507618},
};

TEST(JdDPhase, ParametersMatchTable) {
  for (const ParamRow& r : kParamTable) {
    SCOPED_TRACE(testing::Message() << "d = " << r.d);
    const JdDParams p = jdd_params(r.d);
    EXPECT_NEAR(p.g_hg / r.g_hg, 1.0, 1e-5);
    EXPECT_NEAR(p.g_d / r.g_d, 1.0, 1e-5);
    EXPECT_NEAR(p.alpha / r.alpha, 1.0, 1e-5);
    EXPECT_NEAR(p.w_d / r.w_d, 1.0, 1e-5);
  }
  // The two known transcription errors would be caught: 0.664888 in w_D shifts it by
  // 0.1 % (100x the tolerance); exp(...) - 0.428934 for g_D gives a negative g.
  const double w_wrong = std::exp(-0.599085 / (10.0 - 0.641583) - 0.664888);
  EXPECT_GT(std::fabs(w_wrong / jdd_params(10.0).w_d - 1.0), 1e-3);
}

TEST(JdDPhase, DiameterIsClampedToTheFitRange) {
  const JdDParams lo = jdd_params(2.0), at5 = jdd_params(5.0);
  const JdDParams hi = jdd_params(80.0), at50 = jdd_params(50.0);
  EXPECT_EQ(lo.g_hg, at5.g_hg);
  EXPECT_EQ(lo.w_d, at5.w_d);
  EXPECT_EQ(hi.alpha, at50.alpha);
  EXPECT_EQ(hi.g_d, at50.g_d);
  const JdDParams nan = jdd_params(std::nan(""));
  EXPECT_TRUE(std::isfinite(nan.g_hg) && std::isfinite(nan.g_d) && std::isfinite(nan.alpha) &&
              std::isfinite(nan.w_d));
}

// Phase values (sr^-1) from docs/SOURCES.md at 0, 90 and 180 degrees.
TEST(JdDPhase, ValuesAtKeyAngles) {
  struct Row {
    double d, p0, p90, p180;
  };
  const Row rows[] = {{10.0, 586.86, 1.72563e-3, 1.2715e-2}, {20.0, 2742.51, 1.14718e-3, 1.0914e-2}};
  for (const Row& r : rows) {
    SCOPED_TRACE(testing::Message() << "d = " << r.d);
    const JdDParams p = jdd_params(r.d);
    EXPECT_NEAR(jdd_phase(1.0, p) / r.p0, 1.0, 1e-3);
    EXPECT_NEAR(jdd_phase(0.0, p) / r.p90, 1.0, 1e-3);
    EXPECT_NEAR(jdd_phase(-1.0, p) / r.p180, 1.0, 1e-3);
  }
}

// Each lobe and the blend integrate to 1 over the sphere for d = 5 .. 50 (step 2.5).
TEST(JdDPhase, NormalisedOverTheSphere) {
  double worst = 0.0;
  for (double d = 5.0; d <= 50.0 + 1e-9; d += 2.5) {
    SCOPED_TRACE(testing::Message() << "d = " << d);
    const JdDParams p = jdd_params(d);
    const double hg = integrate_sphere([&](double mu) { return hg_phase(mu, p.g_hg); });
    const double dr =
        integrate_sphere([&](double mu) { return draine_phase(mu, p.g_d, p.alpha); });
    const double all = integrate_sphere([&](double mu) { return jdd_phase(mu, p); });
    EXPECT_NEAR(hg, 1.0, 1e-3);
    EXPECT_NEAR(dr, 1.0, 1e-3);
    EXPECT_NEAR(all, 1.0, 1e-3);
    worst = std::max({worst, std::fabs(hg - 1.0), std::fabs(dr - 1.0), std::fabs(all - 1.0)});
  }
  std::printf("worst |int p dOmega - 1| over d = 5..50: %.3g\n", worst);
}

// Mean cosine: docs/SOURCES.md (4 decimals), the closed form, and the integral.
TEST(JdDPhase, MeanCosine) {
  const double table[][2] = {{5.0, 0.8434}, {10.0, 0.8642}, {20.0, 0.8793}, {50.0, 0.8912}};
  for (const auto& row : table) {
    SCOPED_TRACE(testing::Message() << "d = " << row[0]);
    const JdDParams p = jdd_params(row[0]);
    const double closed = jdd_mean_cosine(p);
    const double integral = integrate_sphere([&](double mu) { return mu * jdd_phase(mu, p); });
    EXPECT_NEAR(closed, row[1], 5e-5);
    EXPECT_NEAR(integral, closed, 1e-6);
  }
}

// The HG lobe is evaluated without cancellation at the forward peak: p(1) equals the
// closed form (1 + g) / (4 pi (1 - g)^2) to round-off even for g -> 1, where
// 1 + g^2 - 2g loses ~12 digits.
TEST(JdDPhase, ForwardPeakWithoutCancellation) {
  for (double g : {0.9, 0.99, 0.997952, 0.999999}) {
    const double exact = (1.0 + g) / (4.0 * kPi * (1.0 - g) * (1.0 - g));
    EXPECT_NEAR(hg_phase(1.0, g) / exact, 1.0, 1e-12) << g;
  }
  // Isotropic limit and back-scatter closed form.
  EXPECT_NEAR(hg_phase(0.3, 0.0), 1.0 / (4.0 * kPi), 1e-15);
  EXPECT_NEAR(hg_phase(-1.0, 0.5), (1.0 - 0.5) / (4.0 * kPi * 1.5 * 1.5), 1e-15);
  // alpha = 0 reduces Draine to HG.
  EXPECT_DOUBLE_EQ(draine_phase(0.2, 0.6, 0.0), hg_phase(0.2, 0.6));
}

// Positive and finite at every angle and diameter (no NaN may reach a frame).
TEST(JdDPhase, PositiveAndFinite) {
  for (double d = 5.0; d <= 50.0; d += 0.5) {
    const JdDParams p = jdd_params(d);
    for (int i = 0; i <= 2000; ++i) {
      const double mu = -1.0 + i * 0.001;
      const double v = jdd_phase(mu, p);
      ASSERT_TRUE(std::isfinite(v) && v > 0.0) << d << " " << mu;
    }
  }
}

// ---------------------------------------------------------------------------------
// Droplet optics: sigma_t = N0 Q_ext pi r^2.

TEST(DropletOptics, ExtinctionFromMicrophysics) {
  // Bouthors et al. 2008 §3.2: N0 = 300 cm^-3, d = 14 um (r_e = 7 um); Q_ext = 2.
  const double expected = 3e8 * 2.0 * kPi * 7e-6 * 7e-6;  // = 0.0923628 m^-1
  EXPECT_NEAR(cloud_extinction_per_m(14.0), expected, 1e-15);
  EXPECT_NEAR(cloud_extinction_per_m(14.0), 0.0924, 1e-4);
  // Mean free path 1/sigma ~ 10.8 m: between 10 and 20 m (Bouthors et al. 2008 §3.1:
  // several metres).
  EXPECT_GT(1.0 / cloud_extinction_per_m(14.0), 10.0);
  EXPECT_LT(1.0 / cloud_extinction_per_m(14.0), 20.0);
  // Scaling: d^2, N0 and Q_ext; Q_ext = 1 doubles the path (~21.7 m, Bouthors et al. 2008
  // §3.1: "20 m").
  EXPECT_NEAR(cloud_extinction_per_m(28.0) / cloud_extinction_per_m(14.0), 4.0, 1e-12);
  EXPECT_NEAR(cloud_extinction_per_m(14.0, 1.5e8) / cloud_extinction_per_m(14.0), 0.5, 1e-12);
  EXPECT_NEAR(1.0 / cloud_extinction_per_m(14.0, 3e8, 1.0), 21.65, 0.01);
  EXPECT_EQ(cloud_extinction_per_m(0.0), 0.0);
}

}  // namespace
