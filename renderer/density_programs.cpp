#include "renderer/density_programs.h"

#include <utility>

#include "weather/cumulus_domes.h"

namespace cloudsvc {

bool density_loops_fit(const RenderQuality& q) {
  constexpr double kLoopIterationBudget = 65535.0;  // llvmpipe, per invocation (gallivm)
  constexpr double kMarchOverhead = 4.0;
  // a lit sample's own column, where marched, is that many base-shape evaluations more
  const double evals = static_cast<double>(q.primary_steps) * (1.0 + q.light_steps + marched_column_steps(q));
  return kMarchOverhead * evals * (1.0 + weather::kDomeLevels) <= kLoopIterationBudget;
}

DensityPrograms::DensityPrograms(std::string file, std::vector<std::string> defines)
    : file_(std::move(file)), defines_(std::move(defines)) {}

void DensityPrograms::use(bool domes, bool loops, bool tiling) const {
  const int dome_variant = domes ? (loops ? 2 : 1) : 0;
  std::optional<gl::ShaderProgram>& p = variant_[dome_variant + (tiling ? 3 : 0)];
  if (!p) {
    std::vector<std::string> d = defines_;
    if (domes) d.push_back("CLOUDSVC_CUMULUS_DOMES");
    if (dome_variant == 2) d.push_back("CLOUDSVC_DENSITY_LOOPS");
    if (tiling) d.push_back("CLOUDSVC_NOISE_TILING");
    p.emplace(gl::ShaderProgram::compute(file_, d));
  }
  p->use();
}

}  // namespace cloudsvc
