// Tabulated Lorenz-Mie phase function (see mie_phase_table.h).
#include "renderer/model/mie_phase_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "renderer/model/mie.h"

namespace cloudsvc::model {

namespace {

constexpr double kForwardStepDeg = kPhaseTableForwardEndDeg / kPhaseTableForwardIntervals;
constexpr double kRearStepDeg = (180.0 - kPhaseTableForwardEndDeg) / kPhaseTableRearIntervals;
constexpr double kDeg = std::numbers::pi / 180.0;

// Solid-angle integral of p over the ring between samples i and i + 1, with p linear in the
// angle from pa to pb: 2 pi int p(theta) sin(theta) dtheta; p is linear and sin smooth on
// the interval, so 3-point Gauss-Legendre is exact to ~1e-12.
double interval_integral(int i, double pa, double pb) {
  static const double kNodes[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  static const double kWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const double a = phase_table_angle_deg(i) * kDeg, b = phase_table_angle_deg(i + 1) * kDeg;
  double sum = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double u = 0.5 * (1.0 + kNodes[k]);
    sum += 0.5 * (b - a) * kWeights[k] * (pa + (pb - pa) * u) * std::sin(a + (b - a) * u);
  }
  return 2.0 * std::numbers::pi * sum;
}

double sphere_integral(const std::vector<glm::dvec3>& p, int channel) {
  double sum = 0.0;
  for (int i = 0; i + 1 < kPhaseTableSamples; ++i)
    sum += interval_integral(i, p[static_cast<std::size_t>(i)][channel], p[static_cast<std::size_t>(i + 1)][channel]);
  return sum;
}

}  // namespace

const char* cloud_phase_model_name(CloudPhaseModel m) { return m == CloudPhaseModel::kMie ? "mie" : "fit"; }

std::optional<CloudPhaseModel> cloud_phase_model_from_name(std::string_view name) {
  if (name == "fit") return CloudPhaseModel::kFit;
  if (name == "mie") return CloudPhaseModel::kMie;
  return std::nullopt;
}

double phase_table_angle_deg(int i) {
  if (i <= kPhaseTableForwardIntervals) return i * kForwardStepDeg;
  return kPhaseTableForwardEndDeg + (i - kPhaseTableForwardIntervals) * kRearStepDeg;
}

double phase_table_position(double theta_deg) {
  const double t = std::clamp(theta_deg, 0.0, 180.0);
  if (t <= kPhaseTableForwardEndDeg) return t / kForwardStepDeg;
  return kPhaseTableForwardIntervals + (t - kPhaseTableForwardEndDeg) / kRearStepDeg;
}

glm::dvec3 PhaseTable::at_angle_deg(double theta_deg) const {
  const double x = phase_table_position(theta_deg);
  const int i = std::min(static_cast<int>(x), kPhaseTableSamples - 2);
  const double f = x - i;
  return phase[static_cast<std::size_t>(i)] * (1.0 - f) + phase[static_cast<std::size_t>(i + 1)] * f;
}

glm::dvec3 PhaseTable::at_cos(double cos_theta) const {
  return at_angle_deg(std::acos(std::clamp(cos_theta, -1.0, 1.0)) / kDeg);
}

PhaseTable compute_mie_phase_table(double mean_diameter_um, double relative_spread, int threads) {
  if (!(mean_diameter_um > 0.0) || !(relative_spread > 0.0))
    throw std::invalid_argument("compute_mie_phase_table: diameter and spread must be > 0");
  std::vector<double> cos_theta(kPhaseTableSamples);
  for (int i = 0; i < kPhaseTableSamples; ++i) cos_theta[static_cast<std::size_t>(i)] = std::cos(phase_table_angle_deg(i) * kDeg);
  cos_theta.back() = -1.0;

  PhaseTable t;
  t.mean_diameter_um = mean_diameter_um;
  t.relative_spread = relative_spread;
  t.phase.assign(kPhaseTableSamples, glm::dvec3(0.0));
  for (int c = 0; c < 3; ++c) {
    DropletSpectrum s;
    s.mean_diameter_um = mean_diameter_um;
    s.relative_spread = relative_spread;
    s.shape = DropletShape::kGamma;
    s.wavelength_um = kRenderedWavelengthsUm[c];
    s.m = {kWaterRealIndexRgb[c], kWaterIndex550nm.imag()};
    s.size_parameter_step = kPhaseTableSizeStep;
    const MieAverage avg = mie_size_average(s, cos_theta, threads);
    for (int i = 0; i < kPhaseTableSamples; ++i) t.phase[static_cast<std::size_t>(i)][c] = avg.phase[static_cast<std::size_t>(i)];
    t.g[c] = avg.g;
    t.effective_diameter_um = avg.effective_diameter_um;  // the same for every wavelength
  }
  for (int c = 0; c < 3; ++c) {
    t.normalisation[c] = sphere_integral(t.phase, c);
    for (glm::dvec3& p : t.phase) p[c] /= t.normalisation[c];
  }
  for (int c = 0; c < 3; ++c) {
    std::vector<double>& cdf = t.cdf[static_cast<std::size_t>(c)];
    cdf.assign(kPhaseTableSamples, 0.0);
    for (int i = 0; i + 1 < kPhaseTableSamples; ++i)
      cdf[static_cast<std::size_t>(i + 1)] = cdf[static_cast<std::size_t>(i)] +
                                             interval_integral(i, t.phase[static_cast<std::size_t>(i)][c],
                                                               t.phase[static_cast<std::size_t>(i + 1)][c]);
    for (double& v : cdf) v /= cdf.back();
  }
  return t;
}

PhaseTableFuture mie_phase_table_future(double mean_diameter_um) {
  static std::mutex mutex;
  static std::map<long, PhaseTableFuture> cache;
  const long key = std::lround(std::clamp(mean_diameter_um, 5.0, 50.0) * 10.0);
  std::lock_guard<std::mutex> lock(mutex);
  PhaseTableFuture& slot = cache[key];
  if (!slot.valid())
    slot = std::async(std::launch::async, [key] {
             return std::shared_ptr<const PhaseTable>(std::make_shared<const PhaseTable>(compute_mie_phase_table(key / 10.0)));
           }).share();
  return slot;
}

std::shared_ptr<const PhaseTable> mie_phase_table(double mean_diameter_um) {
  return mie_phase_table_future(mean_diameter_um).get();
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return 2.0 * std::atan2(glm::length(a - b), glm::length(a + b));
}

}  // namespace cloudsvc::model
