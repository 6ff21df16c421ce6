// render_bench: median ms/frame of the GPU renderer for each weather preset at 320x180
// and 640x360 (llvmpipe on CPU-only machines), plus density evaluations per pixel.
// Prints a Markdown table (docs/PERFORMANCE.md is generated from it).
//
//   build/bin/render_bench [--frames 5] [--sizes 320x180,640x360]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "weather/presets.h"

namespace {

struct Size { int w, h; };

std::vector<Size> parse_sizes(const std::string& text) {
  std::vector<Size> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    Size s{};
    if (std::sscanf(item.c_str(), "%dx%d", &s.w, &s.h) != 2 || s.w <= 0 || s.h <= 0 || s.w > 8192 || s.h > 8192)
      throw CLI::ValidationError("--sizes", "expected WxH[,WxH...], got " + item);
    out.push_back(s);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Median frame time of each weather preset (standard view: 300 m, below every layer, looking 10 deg up, 14:00 UTC)"};
  int frames = 5;
  std::string sizes_text = "320x180,640x360";
  app.add_option("--frames", frames, "frames per measurement (median; the first, with shader JIT, is dropped)")
      ->check(CLI::Range(2, 1000));
  app.add_option("--sizes", sizes_text, "comma-separated image sizes WxH");
  CLI11_PARSE(app, argc, argv);
  std::vector<Size> sizes;
  try {
    sizes = parse_sizes(sizes_text);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  }

  cloudsvc::gl::EglContext context;
  cloudsvc::CloudRenderer renderer;
  std::printf("# render_bench on %s\n\n", context.description().c_str());
  std::printf("| preset | size | median ms | min ms | density evals/px | cloud px %% |\n");
  std::printf("|---|---|---:|---:|---:|---:|\n");
  for (const std::string& name : cloudsvc::weather::preset_names()) {
    renderer.set_weather(*cloudsvc::weather::preset(name));
    for (const Size& s : sizes) {
      cloudsvc::ViewRequest v;
      v.position = {47.45, 8.56, 300.0};
      v.attitude = {135.0, 10.0, 0.0};
      v.unix_time_s = *cloudsvc::geo::parse_utc_iso8601("2026-06-21T14:00:00Z");
      v.fov_deg = 75.0;
      v.width = s.w;
      v.height = s.h;
      std::vector<double> ms;
      double evals = 0.0, cloud = 0.0;
      for (int i = 0; i < frames; ++i) {
        v.frame_index = static_cast<std::uint32_t>(i);
        const cloudsvc::FrameImage img = renderer.render(v);
        if (i > 0) ms.push_back(img.stats.render_ms);
        evals = img.stats.density_evals_per_pixel;
        cloud = 100.0 * static_cast<double>(img.stats.cloud_pixels) / (double(s.w) * s.h);
      }
      std::sort(ms.begin(), ms.end());
      std::printf("| %s | %dx%d | %.1f | %.1f | %.1f | %.1f |\n", name.c_str(), s.w, s.h, ms[ms.size() / 2], ms.front(),
                  evals, cloud);
      std::fflush(stdout);
    }
  }
  return 0;
}
