// render_bench: median ms/frame of the GPU renderer for each weather preset at 320x180
// and 640x360 (llvmpipe on CPU-only machines), plus density evaluations per pixel.
// Prints a Markdown table (docs/PERFORMANCE.md is generated from it).
//
//   build/bin/render_bench [--frames 5] [--sizes 320x180,640x360] [--quality default]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "geodesy/utc_time.h"
#include "renderer/cloud_renderer.h"
#include "renderer/quality_presets.h"
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
  std::string sizes_text = "320x180,640x360", quality_name = "default";
  app.add_option("--frames", frames, "frames per measurement (median; the first, with shader JIT, is dropped)")
      ->check(CLI::Range(2, 1000));
  app.add_option("--sizes", sizes_text, "comma-separated image sizes WxH");
  app.add_option("--quality", quality_name, "quality preset (renderer/quality_presets.h); with temporal reuse "
                                            "the frames after the first are amortised");
  CLI11_PARSE(app, argc, argv);
  std::vector<Size> sizes;
  try {
    sizes = parse_sizes(sizes_text);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  }

  const auto quality = cloudsvc::quality_preset(quality_name);
  if (!quality) {
    std::fprintf(stderr, "render_bench: unknown --quality %s\n", quality_name.c_str());
    return 2;
  }
  cloudsvc::gl::EglContext context;
  cloudsvc::CloudRenderer renderer;
  std::printf("# render_bench on %s, quality %s\n\n", context.description().c_str(), quality_name.c_str());
  std::printf("| preset | size | median ms | min ms | density evals/px | cloud px %% | march | resolve | composite | other |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  // every preset from the standard view, then above the overcast deck looking up (no ray
  // meets a layer: no cloud march at all)
  std::vector<std::pair<std::string, double>> rows;
  for (const std::string& name : cloudsvc::weather::preset_names()) rows.push_back({name, 300.0});
  rows.push_back({"overcast-stratus", 3000.0});
  for (const auto& [name, alt] : rows) {
    renderer.set_weather(*cloudsvc::weather::preset(name));
    for (const Size& s : sizes) {
      cloudsvc::ViewRequest v;
      v.position = {47.45, 8.56, alt};
      v.attitude = {135.0, alt > 1000.0 ? 40.0 : 10.0, 0.0};  // above the deck: the whole view above the horizon
      v.unix_time_s = *cloudsvc::geo::parse_utc_iso8601("2026-06-21T14:00:00Z");
      v.fov_deg = 75.0;
      v.width = s.w;
      v.height = s.h;
      std::vector<double> ms;
      double evals = 0.0, cloud = 0.0;
      std::vector<double> march, resolve, composite, other;  // per-pass ms of the timed frames
      for (int i = 0; i < frames; ++i) {
        v.frame_index = static_cast<std::uint32_t>(i);
        v.reset_history = i == 0;
        const cloudsvc::FrameImage img = renderer.render(v, *quality);
        if (i > 0) {
          const cloudsvc::FrameStats& st = img.stats;
          ms.push_back(st.render_ms);
          march.push_back(st.march_ms);
          resolve.push_back(st.resolve_ms);
          composite.push_back(st.composite_ms);
          other.push_back(st.render_ms - st.march_ms - st.resolve_ms - st.composite_ms);
        }
        evals = img.stats.density_evals_per_pixel;
        cloud = 100.0 * static_cast<double>(img.stats.cloud_pixels) / (double(s.w) * s.h);
      }
      std::sort(ms.begin(), ms.end());
      auto med = [](std::vector<double> v) { std::sort(v.begin(), v.end()); return v[v.size() / 2]; };
      const std::string label = alt > 1000.0 ? name + " (above it, looking up)" : name;
      std::printf("| %s | %dx%d | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", label.c_str(), s.w, s.h,
                  ms[ms.size() / 2], ms.front(), evals, cloud, med(march), med(resolve), med(composite), med(other));
      std::fflush(stdout);
    }
  }
  return 0;
}
