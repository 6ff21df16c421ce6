// `cloudsvc render` and `cloudsvc demo` (in progress).
#include "service/commands.h"

namespace cloudsvc {
int run_render(const RenderOptions&) { return 1; }
int run_demo(const DemoOptions&) { return 1; }
}  // namespace cloudsvc
