// Quality presets, chosen from the Pareto front of bench/cloudbench.cpp (first run,
// docs/ACCURACY.md: error at 32x18 vs the CPU reference, cost at 160x90, summed over the
// 8 benchmark scenes; ms on llvmpipe, 2 cores; PSNR mean / worst scene):
//   naive   uniform 64 primary, 6 light, 3 octaves   1123 ms  39.1 / 25.0 dB  (baseline)
//   low     24 primary (log), 3 light                  731 ms  33.2 / 20.5 dB  (0.65x naive)
//   medium  64 primary (log), 4 light                 1102 ms  39.7 / 25.7 dB  (naive's cost, +0.7 dB)
//   default 64 primary (log), 6 light                 1274 ms  40.8 / 25.7 dB  (RenderQuality{})
//   high    96 primary (log), 8 light                 1751 ms  43.0 / 26.2 dB
//   ultra   192 primary (log), 12 light               3312 ms  46.9 / 29.8 dB
// Log steps: uniform in ln(1 + t / 1 km). Fewer than 3 light steps or other octave counts
// leave the front (2 light steps: worst scene 14 dB). Skipping and temporal reuse (issue 5)
// will move the whole front; re-run cloudbench and re-choose then.
#include "renderer/quality_presets.h"

namespace cloudsvc {
namespace {

RenderQuality march(int primary, int light, int octaves, double step_growth_ref_m) {
  RenderQuality q;
  q.primary_steps = primary;
  q.light_steps = light;
  q.ms_octaves = octaves;
  q.step_growth_ref_m = step_growth_ref_m;
  return q;
}

struct Named {
  const char* name;
  RenderQuality quality;
};

const std::vector<Named>& presets() {
  static const std::vector<Named> p = {
      {"naive", march(64, 6, 3, 0.0)},
      {"low", march(24, 3, 3, 1000.0)},
      {"medium", march(64, 4, 3, 1000.0)},
      {"high", march(96, 8, 3, 1000.0)},
      {"ultra", march(192, 12, 3, 1000.0)},
      {"default", march(64, 6, 3, 1000.0)},
  };
  return p;
}

}  // namespace

std::optional<RenderQuality> quality_preset(std::string_view name) {
  for (const Named& n : presets())
    if (name == n.name) return n.quality;
  return std::nullopt;
}

const std::vector<std::string>& quality_preset_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const Named& n : presets()) v.emplace_back(n.name);
    return v;
  }();
  return names;
}

}  // namespace cloudsvc
