// Sub-commands of the cloudsvc executable. Each returns the process exit code.
#pragma once

#include "service/render_options.h"

namespace cloudsvc {

int run_render(const RenderOptions& opt);  // `cloudsvc render`: one view to a file or window
int run_demo(const DemoOptions& opt);      // `cloudsvc demo`: the documented scene set to a folder
int run_serve(const ServeOptions& opt);    // `cloudsvc serve`: the long-running image generator

}  // namespace cloudsvc
