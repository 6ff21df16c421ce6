// Named ray-march quality presets (issue "Accuracy", part 2): RenderQuality values, to be
// chosen from the measured error-vs-time Pareto front of bench/cloudbench.cpp against the
// CPU reference (measured values in quality_presets.cpp and docs/ACCURACY.md). The march code is
// the same for every preset; only the numbers of RenderQuality (renderer/api/render_quality.h) change.
//
//   naive    uniform 64 primary steps (step_growth_ref_m = 0), 6 light steps, 3 octaves:
//            the baseline speed-ups are quoted against
//   low, medium, high, ultra   points of the Pareto front, increasing cost (log steps)
//   default  the recommended preset (= RenderQuality{}: 64 log steps, 6 light steps)
//
// `cloudsvc render --quality reference` (the CPU reference renderer) is not a
// RenderQuality and is handled by the command, not here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/api/frame_image.h"
#include "renderer/api/render_quality.h"
#include "renderer/api/view_request.h"

namespace cloudsvc {

// The preset's RenderQuality, or nullopt for an unknown name (names are lower case).
std::optional<RenderQuality> quality_preset(std::string_view name);

// Every preset name: naive, low, medium, high, ultra (increasing cost), then default.
const std::vector<std::string>& quality_preset_names();

}  // namespace cloudsvc
