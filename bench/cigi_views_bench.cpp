// What several CIGI views (display channels) cost against one (issue: three views at most
// 2.5x one view at the same size). An aircraft flies level at 65 m/s, 10 frames per second;
// each IG frame renders 1 view (the nose) or 3 views (the nose and 60° either side, the
// way `cloudsvc serve --cigi` draws a host's views: one CloudRenderer, one channel per view,
// the weather, sun, LUTs and ground shadow map shared). After --warmup frames (shader
// compilation, first histories) the median wall time of an IG frame over --frames frames is
// compared, at two altitudes: above the layer and inside it. A third case draws the two
// side views at --side-quality (serve --cigi-view-quality ID=PRESET), the nose at default.
//
//   build/bin/cigi_views_bench [--size 640x360] [--frames 20] [--warmup 4] [--weather broken-cumulus]
//                              [--side-quality low]
#include <CLI/CLI.hpp>

#include <chrono>
#include <optional>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/bench_util.h"
#include "renderer/cloud_renderer.h"
#include "renderer/gl/egl_context.h"
#include "renderer/quality_presets.h"
#include "weather/presets.h"

namespace {

using namespace cloudsvc;

constexpr double kStartUtc = 1782036000.0;  // 2026-06-21T10:00:00Z
constexpr double kFrameDt_s = 0.1;
constexpr double kSpeed_mps = 65.0;

// One view of an IG frame: its yaw from the nose (degrees) and its quality preset.
struct ViewCase {
  double yaw_deg;
  RenderQuality quality;
};

// Median wall ms of an IG frame drawing the views, each on its own channel of a fresh
// renderer.
struct Cost {
  double frame_ms = 0.0;  // median wall time of an IG frame
  // means per IG frame, ms: the passes of FrameStats, summed over the frame's views
  double luts = 0.0, shadow = 0.0, march = 0.0, resolve = 0.0, composite = 0.0, readback = 0.0;
};

Cost frame_cost(const weather::Weather& w, double alt_m, const std::vector<ViewCase>& views, int width, int height,
                int warmup, int frames) {
  CloudRenderer renderer;
  renderer.set_weather(w);
  std::vector<double> ms;
  Cost c;
  for (int f = 0; f < warmup + frames; ++f) {
    const double t = f * kFrameDt_s;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t v = 0; v < views.size(); ++v) {
      ViewRequest r;
      // heading 090: eastward at 47.45 N, 1° of longitude = 75.3 km
      r.position = {47.45, 8.56 + kSpeed_mps * t / 75300.0, alt_m};
      r.attitude = {90.0 + views[v].yaw_deg, 0.0, 0.0};
      r.unix_time_s = kStartUtc + t;
      r.width = width;
      r.height = height;
      r.frame_index = static_cast<std::uint32_t>(f + 1);
      r.channel = 1 + static_cast<int>(v);
      const FrameImage img = renderer.render(r, views[v].quality);
      if (f >= warmup) {
        const FrameStats& s = img.stats;
        c.luts += s.luts_ms / frames;
        c.shadow += s.shadow_map_ms / frames;
        c.march += s.march_ms / frames;
        c.resolve += s.resolve_ms / frames;
        c.composite += s.composite_ms / frames;
        c.readback += s.readback_ms / frames;
      }
    }
    const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (f >= warmup) ms.push_back(elapsed);
  }
  c.frame_ms = bench::median(ms);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("cigi_views_bench: the cost of 3 CIGI views against 1 at the same size");
  std::string size = "640x360", weather_name = "broken-cumulus", side_quality = "low";
  int frames = 20, warmup = 4;
  app.add_option("--size", size, "Image size of each view, WxH");
  app.add_option("--frames", frames, "IG frames measured per case");
  app.add_option("--warmup", warmup, "IG frames before measuring");
  app.add_option("--weather", weather_name, "Weather preset");
  app.add_option("--side-quality", side_quality, "Quality preset of the two side views in the third case");
  CLI11_PARSE(app, argc, argv);
  const std::optional<RenderQuality> nose = quality_preset("default"), side = quality_preset(side_quality);
  if (!side) {
    std::fprintf(stderr, "--side-quality %s: unknown preset\n", side_quality.c_str());
    return 2;
  }
  int width = 0, height = 0;
  if (!bench::parse_frame_size(size, width, height)) {
    std::fprintf(stderr, "--size %s: expected WxH\n", size.c_str());
    return 2;
  }
  const std::optional<weather::Weather> w = weather::preset(weather_name);
  if (!w) {
    std::fprintf(stderr, "--weather %s: unknown preset\n", weather_name.c_str());
    return 2;
  }
  gl::EglContext context;
  std::printf("| altitude | views | ms per IG frame | ratio | LUTs | shadow map | march | resolve | composite | "
              "read-back |\n|---|---|---|---|---|---|---|---|---|---|\n");
  const std::string sides = "3, sides " + side_quality;
  for (const double alt : {3000.0, 1500.0}) {
    const Cost one = frame_cost(*w, alt, {{0.0, *nose}}, width, height, warmup, frames);
    const Cost three = frame_cost(*w, alt, {{-60.0, *nose}, {0.0, *nose}, {60.0, *nose}}, width, height, warmup, frames);
    const Cost cheap_sides =
        frame_cost(*w, alt, {{-60.0, *side}, {0.0, *nose}, {60.0, *side}}, width, height, warmup, frames);
    for (const auto& [n, c] :
         {std::pair<std::string, Cost>{"1", one}, std::pair<std::string, Cost>{"3", three}, std::pair{sides, cheap_sides}})
      std::printf("| %.0f m | %s | %.1f | %.2f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", alt, n.c_str(),
                  c.frame_ms, c.frame_ms / one.frame_ms, c.luts, c.shadow, c.march, c.resolve, c.composite, c.readback);
    std::fflush(stdout);
  }
  return 0;
}
