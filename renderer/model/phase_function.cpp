// Jendersie & d'Eon 2023 HG + Draine phase function (see phase_function.h), double
// precision reference for shaders/phase_function.glsl. All phase values in sr^-1.
#include "renderer/model/phase_function.h"

#include <cmath>
#include <numbers>

namespace cloudsvc::model {

namespace {
constexpr double kInv4Pi = 1.0 / (4.0 * std::numbers::pi);
constexpr double kMinDiameterUm = 5.0;   // fit validity range (the paper's d >= 5 fit)
constexpr double kMaxDiameterUm = 50.0;
}  // namespace

// Jendersie & d'Eon 2023, fits for 5 um <= d <= 50 um (the minus signs as in Ford 2024
// eqs. 3.14-3.17, w_D constant 0.665888 as in the paper where Ford 2024 prints 0.664888;
// the constant in g_D sits inside the exp; docs/SOURCES.md).
JdDParams jdd_params(double diameter_um) {
  // Clamp into the fit's range; NaN maps to the lower bound so no NaN propagates.
  double d = diameter_um;
  if (!(d >= kMinDiameterUm)) d = kMinDiameterUm;
  if (d > kMaxDiameterUm) d = kMaxDiameterUm;
  JdDParams p;
  p.g_hg = std::exp(-0.0990567 / (d - 1.67154));
  p.g_d = std::exp(-2.20679 / (d + 3.91029) - 0.428934);
  p.alpha = std::exp(3.62489 - 8.29288 / (d + 5.52825));
  p.w_d = std::exp(-0.599085 / (d - 0.641583) - 0.665888);
  return p;
}

// Henyey-Greenstein: (1/4pi) (1 - g^2) / (1 + g^2 - 2 g mu)^{3/2}. Written as
// (1 - g)(1 + g) / ((1 - g)^2 + 2 g (1 - mu))^{3/2}: same value, but without the
// cancellations of 1 - g^2 and 1 + g^2 - 2g when g -> 1 (g_HG = 0.998 at d = 50), which
// would cost ~6 digits of the forward peak.
double hg_phase(double cos_theta, double g) {
  const double one_minus_g = 1.0 - g;
  const double denom = one_minus_g * one_minus_g + 2.0 * g * (1.0 - cos_theta);
  return kInv4Pi * one_minus_g * (1.0 + g) / (denom * std::sqrt(denom));
}

// Draine 2003 (ApJ 598, 1017) lobe, normalised over the sphere:
//   p_D = p_HG(mu; g) (1 + alpha mu^2) / (1 + alpha (1 + 2 g^2) / 3).
double draine_phase(double cos_theta, double g, double alpha) {
  const double norm = 1.0 + alpha * (1.0 + 2.0 * g * g) / 3.0;
  return hg_phase(cos_theta, g) * (1.0 + alpha * cos_theta * cos_theta) / norm;
}

double jdd_phase(double cos_theta, const JdDParams& p) {
  return (1.0 - p.w_d) * hg_phase(cos_theta, p.g_hg) +
         p.w_d * draine_phase(cos_theta, p.g_d, p.alpha);
}

// <mu>_HG = g; <mu>_Draine = g (1 + alpha (3 + 2 g^2) / 5) / (1 + alpha (1 + 2 g^2) / 3)
// (Draine 2003); values in docs/SOURCES.md.
double jdd_mean_cosine(const JdDParams& p) {
  const double g = p.g_d;
  const double gd = g * (1.0 + p.alpha * (3.0 + 2.0 * g * g) / 5.0) /
                    (1.0 + p.alpha * (1.0 + 2.0 * g * g) / 3.0);
  return (1.0 - p.w_d) * p.g_hg + p.w_d * gd;
}

}  // namespace cloudsvc::model
