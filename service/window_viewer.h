// `cloudsvc render --window`: the same view in a GLFW window, with keyboard controls
// (see docs/CLI.md). Needs an X display (or xvfb-run).
#pragma once

#include "service/render_options.h"

namespace cloudsvc {

int run_window(const RenderOptions& opt);

}  // namespace cloudsvc
