// Quality presets, chosen from the Pareto front of bench/cloudbench.cpp (docs/ACCURACY.md,
// docs/PERFORMANCE.md: error at 160x90 vs the CPU reference's 3 x 3-ray pixel footprint
// after 17 frames of a still view, amortised cost at 160x90, summed over the 8 benchmark
// scenes; llvmpipe, 2 cores; speed, march work (density evaluations) and RMSE relative to
// naive, 2026-12-02, one run; cost-only runs the same day: default 5.3-6.1x):
//   naive    uniform 64 primary, 6 light, no skips, pixel centre        1.0x,   1.0x work, RMSE 1.00
//   low      64 log, 6 light, long steps x4, LOD, half res, 1/16 px     8.4x, 101x work, RMSE 1.60
//   medium   64 log, 4 light, long steps x2, 1/16 px per frame          4.7x,  24x work, RMSE 1.01
//   default  64 log, 6 light, long steps x2, 1/16 px per frame          4.8x,  20x work, RMSE 0.94
//   high     96 log, 8 light, long steps x2, 1/4 px per frame           2.1x,   3x work, RMSE 0.65
//   ultra    192 log, 12 light, every pixel, accumulated while still    0.5x, 0.3x work, RMSE 0.45
// high and ultra read the diffuse light's depths from each lit sample's own column (8 steps;
// own_columns below), the others from a homogeneous layer of the map's coverage; their RMSE
// above is against the reference of the homogeneous layer (before they took the columns).
// All: the same light model otherwise (peak beam + diffuse source, shaders/cloud_lighting.glsl), the coverage
// pyramid and the light-march cut-off (RenderQuality defaults; not in naive); every
// temporal preset samples the pixel footprint (footprint_jitter). 1/16 px per frame becomes
// 1/4 while the clouds move by more than a pixel per frame (reuse() below). Log steps:
// uniform in ln(1 + t / 1 km). A single frame (or the first after a teleport) has no
// history and marches every pixel, each through its footprint point of that frame index.
#include "renderer/quality_presets.h"

namespace cloudsvc {
namespace {

RenderQuality march(int primary, int light, double step_growth_ref_m) {
  RenderQuality q;
  q.primary_steps = primary;
  q.light_steps = light;
  q.step_growth_ref_m = step_growth_ref_m;
  return q;
}

// 1/16 px per frame falls back to 1/4 while the clouds move by more than a pixel per
// frame: then the history is resampled at a new sub-pixel position every frame, and a
// pixel's single cloud depth misplaces parallax by more than a pixel within the 16-frame
// refresh (measured by cloudbench --sequence, docs/PERFORMANCE.md).
RenderQuality reuse(RenderQuality q, int stride) {
  q.temporal_reuse = true;
  q.temporal_stride = stride;
  if (stride == 4) q.fast_motion_px = 1.0;
  // each frame's sample through another point of the pixel: the accumulated history is the
  // pixel's footprint average (antialiasing), the quantity cloudbench's reference is
  // (docs/STABILITY.md, "2. Smoothness")
  q.footprint_jitter = true;
  return q;
}

RenderQuality naive() {
  RenderQuality q = march(64, 6, 0.0);
  q.long_step_factor = 1;
  q.ground_shadow_map = false;
  q.coverage_pyramid = false;
  q.light_march_cutoff = 0.0;
  return q;
}

RenderQuality low() {
  RenderQuality q = reuse(march(64, 6, 1000.0), 4);
  q.long_step_factor = 4;
  q.level_of_detail = true;
  q.cloud_resolution_divisor = 2;
  return q;
}

// The diffuse light's depths from each lit sample's own vertical column, marched in
// `steps` base-shape steps (RenderQuality::column_steps with column_volume off: the column
// volume's texels blur the columns of cumulus, docs/ACCURACY.md section 0). Against the
// path-traced truth this takes the cloud error from the homogeneous layer's ~0.37 to ~0.25
// on the random scenes, for +24 % of a frame at high and ultra (docs/PERFORMANCE.md
// "Column depths"): more than issue 16 allows the default, so only the two costliest
// presets carry it.
RenderQuality own_columns(RenderQuality q, int steps) {
  q.column_steps = steps;
  q.column_volume = false;
  return q;
}

struct Named {
  const char* name;
  RenderQuality quality;
};

const std::vector<Named>& presets() {
  static const std::vector<Named> p = {
      {"naive", naive()},
      {"low", low()},
      {"medium", reuse(march(64, 4, 1000.0), 4)},
      {"high", own_columns(reuse(march(96, 8, 1000.0), 2), 8)},
      {"ultra", own_columns(reuse(march(192, 12, 1000.0), 1), 8)},
      {"default", reuse(RenderQuality{}, 4)},
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
